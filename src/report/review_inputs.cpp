#include "report/review_inputs.h"

namespace pd {

void load_review_inputs(const ReviewArgs& args, double tolerance, ReviewInputs& out) {
  if (!args.fail_on.empty()) out.options.fail_on = parse_fail_on(args.fail_on);
  if (out.options.fail_on == FailOn::kNew && args.baseline.empty())
    throw ReviewArgsError("--fail-on new needs --baseline (a previous report)");
  if (!args.baseline.empty()) out.baseline = load_baseline(args.baseline);
  if (!args.suppressions.empty()) out.suppressions = load_suppressions(args.suppressions);
  out.options.baseline = out.baseline ? &*out.baseline : nullptr;
  out.options.suppressions = out.suppressions ? &*out.suppressions : nullptr;
  out.options.allow_stale = args.allow_stale;
  out.options.today = utc_today();
  out.options.tolerance = tolerance;
}

}  // namespace pd
