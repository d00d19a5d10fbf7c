// What a depth solve returns (result.h): stop reasons named, stats summed
// keeping the least conclusive reason.
#include <gtest/gtest.h>

#include <set>

#include "solve/result.h"

using namespace pd;

TEST(Result, StopReasonNamesAreDistinct) {
  std::set<std::string> names;
  for (const StopReason r : {StopReason::kNone, StopReason::kProvenSeparated, StopReason::kContact,
                             StopReason::kEpaCertificate, StopReason::kCertificate,
                             StopReason::kBayesian, StopReason::kCap, StopReason::kAboveTolerance})
    EXPECT_TRUE(names.insert(stop_reason_name(r)).second) << stop_reason_name(r);
  EXPECT_STREQ(stop_reason_name(StopReason::kProvenSeparated), "proven_separated");
  EXPECT_STREQ(stop_reason_name(StopReason::kCap), "cap");
  EXPECT_STREQ(stop_reason_name(StopReason::kAboveTolerance), "above_tolerance");
}

TEST(Result, AboveToleranceIsNoLessConclusiveThanTheCertificateItRestsOn) {
  SolveStats capped, above;
  capped.stop_reason = StopReason::kCap;
  above.stop_reason = StopReason::kAboveTolerance;
  SolveStats sum = above;
  sum += capped;
  EXPECT_EQ(sum.stop_reason, StopReason::kCap);
  SolveStats epa;
  epa.stop_reason = StopReason::kEpaCertificate;
  epa += above;
  EXPECT_EQ(epa.stop_reason, StopReason::kAboveTolerance);
}

TEST(Result, StatsAddUpAndKeepTheLeastConclusiveReason) {
  SolveStats a, b;
  a.alpha_evaluations = 10;
  a.local_solves = 1;
  a.distinct_optima = 2;
  a.ipopt_iterations = 3;
  a.ipopt_calls = 4;
  a.ipopt_failures = 5;
  a.mlsl_iterations = 6;
  a.stop_reason = StopReason::kCap;
  b = a;
  b.stop_reason = StopReason::kCertificate;
  SolveStats sum = b;
  sum += a;
  EXPECT_EQ(sum.alpha_evaluations, 20);
  EXPECT_EQ(sum.local_solves, 2);
  EXPECT_EQ(sum.distinct_optima, 4);
  EXPECT_EQ(sum.ipopt_iterations, 6);
  EXPECT_EQ(sum.ipopt_calls, 8);
  EXPECT_EQ(sum.ipopt_failures, 10);
  EXPECT_EQ(sum.mlsl_iterations, 12);
  EXPECT_EQ(sum.stop_reason, StopReason::kCap);  // a capped piece leaves the pair capped
  SolveStats none;
  none += b;
  EXPECT_EQ(none.stop_reason, StopReason::kCertificate);
}
