// The report's `rules` section (docs/report-format.md, "rules"): each rule as
// read and what it matched (sets: parts; tests, ignore, expected: pairs), and
// how a merge adds up its shards' sections.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "batch/run_result.h"

namespace pd {

/// The section of a run with rules. The review adds each expected rule's
/// `suppressed` and `exceeded` (report/review_json.h).
nlohmann::ordered_json rules_json(const RuleCoverage& c);

/// The shards' sections as one run's: the same rules (the caller checked
/// hashes.rules), set coverage as any shard has it (every shard resolves the
/// whole scene), pair counts summed. `sections`: one per shard, in any order.
nlohmann::ordered_json merge_rules_sections(
    const std::vector<const nlohmann::ordered_json*>& sections);

}  // namespace pd
