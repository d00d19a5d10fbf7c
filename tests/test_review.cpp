// The review of a run (review.cpp): the --fail-on bar and the exit code it
// gives, with and without a baseline, on hand-built runs (tests/review_runs.h;
// the baseline and suppressions alone: test_baseline.cpp, test_suppressions.cpp;
// the CLI tests run them end to end).
#include <gtest/gtest.h>

#include "report/baseline.h"
#include "report/expected_rules.h"
#include "report/review.h"
#include "review_runs.h"

namespace pd {

using namespace pd::test;

TEST(Review, AnExpectedContactSuppressesTheClearanceViolationAContactIs) {
  ExpectedRules rules;
  Suppression press;
  press.rule = "press fits";
  press.reason = "bearings are pressed in";
  press.max_depth = 0.05;
  press.where = "rules.expected[0]";
  rules.entries.push_back(press);
  rules.by_name.emplace(press.rule, 0);
  ReviewOptions o;
  o.expected = &rules;
  std::vector<PairResult> pairs = {
      pair(0, 1, Status::kClearanceViolation, 0.02), pair(1, 2, Status::kClearanceViolation, 0.0),
      pair(2, 3, Status::kClearanceViolation, 0.0), pair(3, 4, Status::kClearanceViolation, 0.09)};
  pairs[1].distance = 0.0;  // touching
  pairs[2].distance = 0.1;  // apart, closer than the clearance: no contact
  for (PairResult& r : pairs) r.clearance_min = 0.2, r.expected = press.rule;
  const RunResult run = run_with(pairs);
  const auto reviewed = [&](size_t k) {
    return review_pair(run.pairs[k], run.parts, o, FailOn::kClearance);
  };
  EXPECT_TRUE(reviewed(0).suppressed);  // overlapping by 0.02 <= max_depth
  EXPECT_TRUE(reviewed(1).suppressed);
  EXPECT_FALSE(reviewed(2).suppressed);
  EXPECT_TRUE(reviewed(2).fails);
  EXPECT_FALSE(reviewed(3).suppressed);  // deeper than the rule allows
  EXPECT_TRUE(reviewed(3).expected_exceeded);
}

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
