// The report's `groups` (docs/report-format.md, "Groups"): the run's finding
// groups (report/finding_groups.h) with their members, parts, deepest member
// and suggested move. The JSON report, the JSON Lines tail and pdcheck merge
// all write it from this one function.
#pragma once

#include <nlohmann/json.hpp>

#include "batch/run_result.h"
#include "report/finding_groups.h"

namespace pd {

nlohmann::ordered_json groups_json(const FindingGroups& groups, const RunResult& run);

}  // namespace pd
