// The run's warnings as stderr says them: a part's own warnings (a PLY header
// line skipped, a flat part) one line each, and set-up warnings
// (scene/setup_warnings.h) once per kind, with the first part or pair and how
// many more the report lists.
#pragma once

#include <string>
#include <vector>

#include "batch/run_result.h"

namespace pd {

/// Lines without the "pdcheck: warning: " prefix, in part order, then pair order.
std::vector<std::string> warning_lines(const RunResult& run);

}  // namespace pd
