// The review (baseline states, suppressions, --fail-on) in the JSON and JSON
// Lines reports: docs/report-format.md, "Baseline and suppressions".
#pragma once

#include <nlohmann/json.hpp>

#include "report/review.h"

namespace pd {

/// Adds `baseline_state` and `suppressed` to a pair object.
void add_pair_review(nlohmann::ordered_json& pair, const PairReview& review);

/// Adds the review's counts to `summary` (and sets its exit_code), and the
/// `baseline` and `suppressions` sections to `doc` when they were used.
void add_run_review(nlohmann::ordered_json& doc, nlohmann::ordered_json& summary,
                    const Review& review, const ReviewOptions& options);

}  // namespace pd
