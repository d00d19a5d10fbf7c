// The run's verdict in words (report/verdict.h), from a report's summary: the
// HTML banner's and the terminal table's first line.
#include <gtest/gtest.h>

#include "report/verdict.h"

using namespace pd;
using VerdictJson = nlohmann::ordered_json;

namespace {

VerdictJson verdict_summary(long interference, long false_positive, long separated,
                            long exit_code) {
  return {{"parts", 4},
          {"part_errors", 0},
          {"candidate_pairs", interference + false_positive + separated},
          {"separated", separated},
          {"false_positive", false_positive},
          {"interference", interference},
          {"error", 0},
          {"undecided", 0},
          {"unchecked", 0},
          {"exit_code", exit_code}};
}

}  // namespace

TEST(Verdict, PassFailAndTheCounts) {
  const Verdict pass = run_verdict(verdict_summary(0, 2, 3, 0));
  EXPECT_EQ(pass.state, "pass");
  EXPECT_EQ(pass.headline, "PASS: no interference (exit code 0)");
  EXPECT_EQ(pass.counts, "0 interferences, 2 false positives, 3 separated of 5 candidate pairs");
  const Verdict fail = run_verdict(verdict_summary(1, 1, 0, 1));
  EXPECT_EQ(fail.state, "fail");
  EXPECT_EQ(fail.headline, "FAIL: 1 interference (exit code 1)");
  EXPECT_EQ(fail.counts, "1 interference, 1 false positive, 0 separated of 2 candidate pairs");
}

TEST(Verdict, AnIncompleteRunIsNeverAPass) {
  // Exit 3: a pair failed and a part could not be read. No interference among
  // the checked pairs, and still not a pass.
  VerdictJson s = verdict_summary(0, 0, 4, 3);
  s["error"] = 1;
  s["part_errors"] = 1;
  s["unchecked"] = 3;
  const Verdict v = run_verdict(s);
  EXPECT_EQ(v.state, "incomplete");
  EXPECT_EQ(v.headline,
            "INCOMPLETE: not every pair was checked (1 pair failed, 3 unchecked, 1 part "
            "unusable); not a pass (exit code 3)");
  EXPECT_EQ(v.headline.find("PASS"), std::string::npos);
  EXPECT_NE(v.counts.find("1 pair error, 3 unchecked, 1 unusable part"), std::string::npos)
      << v.counts;
  // With an interference among the checked pairs too: said beside it.
  s["interference"] = 2;
  s["undecided"] = 1;
  EXPECT_EQ(run_verdict(s).headline,
            "INCOMPLETE: not every pair was checked (1 undecided, 1 pair failed, 3 unchecked, 1 "
            "part unusable); not a pass, 2 interferences (exit code 3)");
  // A summary without an exit code (hand-made) is judged by its counts.
  s.erase("exit_code");
  EXPECT_EQ(run_verdict(s).state, "incomplete");
  VerdictJson clean = verdict_summary(0, 1, 1, 0);
  clean.erase("exit_code");
  EXPECT_EQ(run_verdict(clean).state, "pass");
}

TEST(Verdict, TheReviewsBarAndSuppressions) {
  // --fail-on new: an unchanged interference does not fail the run.
  VerdictJson quiet = verdict_summary(1, 0, 0, 0);
  quiet["fail_on"] = "new";
  quiet["failing"] = 0;
  EXPECT_EQ(run_verdict(quiet).headline,
            "PASS: no finding fails the run (fail_on new) (exit code 0)");
  VerdictJson new_one = verdict_summary(2, 0, 0, 1);
  new_one["fail_on"] = "new";
  new_one["failing"] = 1;
  EXPECT_EQ(run_verdict(new_one).headline, "FAIL: 1 failing finding (fail_on new) (exit code 1)");
  VerdictJson stale = verdict_summary(0, 0, 1, 1);
  stale["fail_on"] = "interference";
  stale["failing"] = 0;
  EXPECT_EQ(run_verdict(stale).headline, "FAIL: a suppression needs attention (exit code 1)");
  VerdictJson clearance = verdict_summary(0, 0, 1, 1);
  clearance["clearance_violation"] = 1;
  clearance["fail_on"] = "clearance";
  clearance["failing"] = 1;
  const Verdict c = run_verdict(clearance);
  EXPECT_EQ(c.headline, "FAIL: 1 failing finding (fail_on clearance) (exit code 1)");
  EXPECT_NE(c.counts.find("1 clearance violation"), std::string::npos) << c.counts;
  EXPECT_EQ(run_verdict(verdict_summary(0, 0, 0, 2)).headline, "NOTHING CHECKED (exit code 2)");
}
