// The CI inputs of a run or a merge (--baseline, --suppressions, --fail-on,
// --allow-stale-suppressions), read before any work: a malformed file costs no
// solve. docs/ci.md.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

#include "report/baseline.h"
#include "report/review.h"
#include "report/suppressions.h"
#include "user_error.h"

namespace pd {

/// The options as given on the command line ("" = not given).
struct ReviewArgs {
  std::string baseline, suppressions, fail_on;
  bool allow_stale = false;
};

/// A combination that cannot be honoured (--fail-on new without --baseline): exit 2.
struct ReviewArgsError : UserError {
  using UserError::UserError;
};

/// The files read and the options that point into them. Not copyable: `options`
/// holds pointers to `baseline` and `suppressions`.
struct ReviewInputs {
  std::optional<Baseline> baseline;
  std::optional<Suppressions> suppressions;
  std::optional<ExpectedRules> expected;  ///< the run's expected-contact rules
  ReviewOptions options;

  ReviewInputs() = default;
  ReviewInputs(const ReviewInputs&) = delete;
  ReviewInputs& operator=(const ReviewInputs&) = delete;
};

/// Reads the baseline and suppressions files and sets `out.options` (today's
/// date, `tolerance` for the `updated` rule). Throws ReportInputError naming the
/// file and field, or ReviewArgsError.
void load_review_inputs(const ReviewArgs& args, double tolerance, ReviewInputs& out);

}  // namespace pd
