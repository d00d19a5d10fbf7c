// The finding groups for people: one stderr line per group of several findings.
#pragma once

#include <string>

#include "report/writer.h"

namespace pd {

/// "pdcheck: group 3f2a9c1e: 3 findings (bolt-1, bolt-2, plate): moving plate by
/// 0.42 mm along (0, 0, 1) clears 3 of them; deepest plate / bolt-2, depth 0.31 mm"
/// for each group of two or more findings (at most 10, then a count); nothing
/// when every group is a single finding (its finding line says it all).
std::string group_lines(const ReportInput& in);

}  // namespace pd
