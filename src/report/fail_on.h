// The --fail-on bar: which findings make the exit code 1 (docs/ci.md).
#pragma once

#include <optional>
#include <string>

#include "results/pair_result.h"

namespace pd {

enum class FailOn { kInterference, kClearance, kAny, kNew, kNone };

/// One table for the vocabulary: the CLI's choices, the report and the docs.
struct FailOnName {
  FailOn value;
  const char* name;
  const char* meaning;
};
inline constexpr FailOnName kFailOnNames[] = {
    {FailOn::kInterference, "interference", "status interference (depth > tolerance)"},
    {FailOn::kClearance, "clearance", "interference or clearance_violation"},
    {FailOn::kNew, "new",
     "interference or clearance_violation whose baseline_state is new or updated (needs "
     "--baseline)"},
    {FailOn::kAny, "any", "any finding: false_positive too"},
    {FailOn::kNone, "none", "no finding fails the run (exit 3 still does)"},
};

std::optional<FailOn> parse_fail_on(const std::string& name);
const char* fail_on_name(FailOn bar);

/// A finding is a pair that is not clean and not an error: false_positive,
/// interference or clearance_violation. Baselines and suppressions are about findings.
bool is_finding(Status s);

/// Whether a finding of this status reaches the bar, before baseline and
/// suppressions are considered (kNew: the statuses it looks at).
bool reaches_bar(FailOn bar, Status s);

/// The bar when --fail-on is not given: today's behaviour. An interference
/// fails; a clearance violation fails when the scene asked for clearance checks
/// (there is no violation otherwise), i.e. `clearance` then, else `interference`.
FailOn default_fail_on(bool clearance_checked);

}  // namespace pd
