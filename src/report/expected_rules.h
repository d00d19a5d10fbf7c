// Expected-contact rules (scene/rules.h `expected`) as the review sees them:
// one Suppression per rule, so a finding a rule covers up to its max_depth is
// marked `suppressed` by the same path as a reviewed suppressions entry
// (report/review.h), naming the rule. The run builds them from its rules, a
// merge from the report's `rules` section.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "report/suppressions.h"
#include "scene/rules.h"

namespace pd {

struct ExpectedRules {
  std::vector<Suppression> entries;       ///< one per rule, `rule` its name
  std::map<std::string, size_t> by_name;  ///< index into entries
};

ExpectedRules expected_rules_of(const Rules& rules);
/// From a report's `rules` section (docs/report-format.md); an absent
/// `expected` gives none. Throws ReportInputError on a malformed entry.
ExpectedRules expected_rules_of_report(const nlohmann::ordered_json& rules_section,
                                       const std::string& path);

/// Where a suppression comes from, for messages: the suppressions file and
/// entry, or the expected-contact rule.
std::string suppression_origin(const Suppression& s, const std::string& suppressions_path);

}  // namespace pd
