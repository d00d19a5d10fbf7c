// A run's counts and the exit code they imply (results/summary.cpp).
#include <gtest/gtest.h>

#include "results/summary.h"

using namespace pd;

TEST(Summary, AddCountsEachStatusInItsOwnField) {
  Summary s;
  const Status all[] = {Status::kSeparated, Status::kFalsePositive,      Status::kInterference,
                        Status::kError,     Status::kClearanceViolation, Status::kUndecided};
  for (int k = 0; k < 6; ++k)
    for (int n = 0; n <= k; ++n) s.add(all[k]);
  EXPECT_EQ(s.separated, 1);
  EXPECT_EQ(s.false_positive, 2);
  EXPECT_EQ(s.interference, 3);
  EXPECT_EQ(s.error, 4);
  EXPECT_EQ(s.clearance_violation, 5);
  EXPECT_EQ(s.undecided, 6);
}

TEST(Summary, IncompleteWinsOverFindings) {
  EXPECT_EQ(Summary{}.exit_code(), kExitClean);
  Summary fp;
  fp.add(Status::kFalsePositive);  // a false positive is no finding that fails
  EXPECT_FALSE(fp.has_findings());
  EXPECT_EQ(fp.exit_code(), kExitClean);
  for (const Status s : {Status::kInterference, Status::kClearanceViolation}) {
    Summary f;
    f.add(s);
    EXPECT_TRUE(f.has_findings());
    EXPECT_FALSE(f.incomplete());
    EXPECT_EQ(f.exit_code(), kExitFinding);
  }
  // Each way of not checking something: exit 3, findings or not.
  auto with = [](auto set) {
    Summary s;
    s.add(Status::kInterference);
    set(s);
    return s;
  };
  for (const Summary& s :
       {with([](Summary& x) { x.add(Status::kError); }),
        with([](Summary& x) { x.add(Status::kUndecided); }),
        with([](Summary& x) { x.part_errors = 1; }), with([](Summary& x) { x.unchecked = 1; })}) {
    EXPECT_TRUE(s.incomplete());
    EXPECT_EQ(s.exit_code(), kExitIncomplete);
  }
  // Rules' out-of-scope and ignored pairs were not asked for: not incomplete.
  Summary r;
  r.out_of_scope = 5;
  r.ignored = 2;
  EXPECT_EQ(r.exit_code(), kExitClean);
}
