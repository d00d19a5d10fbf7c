// The --fail-on bar (fail_on.cpp): its names, which statuses reach it, and the
// default.
#include <gtest/gtest.h>

#include "report/fail_on.h"

using namespace pd;

TEST(FailOn, NamesRoundTrip) {
  for (const FailOnName& n : kFailOnNames) {
    EXPECT_EQ(parse_fail_on(n.name), n.value) << n.name;
    EXPECT_STREQ(fail_on_name(n.value), n.name);
    EXPECT_NE(std::string(n.meaning), "");
  }
  EXPECT_EQ(std::size(kFailOnNames), 5u);
  EXPECT_EQ(parse_fail_on("Interference"), std::nullopt);
  EXPECT_EQ(parse_fail_on(""), std::nullopt);
  EXPECT_EQ(parse_fail_on("clearance_violation"), std::nullopt);
}

TEST(FailOn, WhichStatusesReachTheBar) {
  const Status all[] = {Status::kSeparated, Status::kFalsePositive,      Status::kInterference,
                        Status::kError,     Status::kClearanceViolation, Status::kUndecided};
  // Per bar, the statuses that reach it, in the order of `all`.
  const std::pair<FailOn, std::vector<bool>> rows[] = {
      {FailOn::kInterference, {false, false, true, false, false, false}},
      {FailOn::kClearance, {false, false, true, false, true, false}},
      {FailOn::kNew, {false, false, true, false, true, false}},
      {FailOn::kAny, {false, true, true, false, true, false}},
      {FailOn::kNone, {false, false, false, false, false, false}},
  };
  for (const auto& [bar, want] : rows)
    for (int k = 0; k < 6; ++k)
      EXPECT_EQ(reaches_bar(bar, all[k]), want[k]) << fail_on_name(bar) << " " << k;
  // Findings: neither a clean pair nor one not checked or decided.
  const bool finding[] = {false, true, true, false, true, false};
  for (int k = 0; k < 6; ++k) EXPECT_EQ(is_finding(all[k]), finding[k]) << k;
}

TEST(FailOn, TheDefaultFollowsTheClearanceCheck) {
  EXPECT_EQ(default_fail_on(false), FailOn::kInterference);
  EXPECT_EQ(default_fail_on(true), FailOn::kClearance);
}
