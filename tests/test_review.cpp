// The review of a run (review.cpp): the --fail-on bar and the exit code it
// gives, with and without a baseline, on hand-built runs (tests/review_runs.h;
// the baseline and suppressions alone: test_baseline.cpp, test_suppressions.cpp;
// the CLI tests run them end to end).
#include <gtest/gtest.h>

#include "report/baseline.h"
#include "report/review.h"
#include "review_runs.h"

namespace pd {

using namespace pd::test;

TEST(FailOn, ExitCodeTable) {
  // One pair of each finding status; the baseline knows the interference.
  const RunResult run = run_with({pair(0, 1, Status::kInterference, 1.0),
                                  pair(1, 2, Status::kClearanceViolation, 0.0),
                                  pair(2, 3, Status::kFalsePositive, 0.05)});
  struct Row {
    std::vector<PairResult> pairs;
    FailOn bar;
    bool with_baseline;
    int code;
  };
  auto only = [&](std::vector<int> ks) {
    std::vector<PairResult> v;
    for (int k : ks) v.push_back(run.pairs[k]);
    return v;
  };
  const Baseline b = parse_baseline(baseline_text(finding("p0", "p1", "interference", 1.0)), "b");
  const Row rows[] = {
      {only({0}), FailOn::kInterference, false, 1},
      {only({1}), FailOn::kInterference, false, 0},
      {only({2}), FailOn::kInterference, false, 0},
      {only({1}), FailOn::kClearance, false, 1},
      {only({2}), FailOn::kClearance, false, 0},
      {only({2}), FailOn::kAny, false, 1},
      {only({0, 1, 2}), FailOn::kNone, false, 0},
      {only({0}), FailOn::kNew, true, 0},
      {only({0, 1}), FailOn::kNew, true, 1},
      {only({0, 2}), FailOn::kNew, true, 0},
      {{}, FailOn::kAny, false, 0},
  };
  for (const Row& row : rows) {
    RunResult r = run;
    r.pairs = row.pairs;
    ReviewOptions opt;
    opt.fail_on = row.bar;
    opt.baseline = row.with_baseline ? &b : nullptr;
    opt.tolerance = 0.1;
    EXPECT_EQ(review_run(r, opt, false).exit_code, row.code)
        << fail_on_name(row.bar) << " with " << row.pairs.size() << " pairs";
    EXPECT_EQ(review_run(r, opt, true).exit_code, 3);
  }
  // The default is today's behaviour: clearance violations fail when asked for.
  RunResult r = run;
  r.pairs = only({1});
  EXPECT_EQ(review_run(r, {}, false).exit_code, 0);
  r.simulated.push_back("clearance");
  EXPECT_EQ(review_run(r, {}, false).exit_code, 1);
  EXPECT_EQ(effective_fail_on(r, {}), FailOn::kClearance);
}

}  // namespace pd
