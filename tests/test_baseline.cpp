// The baseline (baseline.cpp): every finding's state against an earlier
// report, the `updated` rule, and malformed files named by their JSON path.
#include <gtest/gtest.h>

#include "report/baseline.h"
#include "report/review.h"
#include "results/fingerprint.h"
#include "review_runs.h"
#include "tolerances.h"

namespace pd {

using namespace pd::test;

TEST(Baseline, EveryState) {
  // Baseline: p0/p1 interference 1.0 (unchanged), p1/p2 interference 1.0 (deeper
  // now: updated), p0/p2 false_positive (interference now: updated), p0/p3 gone
  // and separated now (absent), p0/p4 culled now (absent), p3/p5 (part failed:
  // unknown), p1/p3 (pair crashed: unknown), p0/gone (part removed: unknown).
  const Baseline b = parse_baseline(
      baseline_text(finding("p1", "p0", "interference", 1.0) + "," +  // A/B order swapped
                    finding("p1", "p2", "interference", 1.0) + "," +
                    finding("p0", "p2", "false_positive", 0.05) + "," +
                    finding("p0", "p3", "interference", 2.0) + "," +
                    finding("p0", "p4", "interference", 2.0) + "," +
                    finding("p3", "p5", "interference", 2.0) + "," +
                    finding("p1", "p3", "interference", 2.0) + "," +
                    finding("p0", "gone", "interference", 2.0) + "," +
                    R"({"a": "p2", "b": "p3", "status": "separated", "depth": 0})"),
      "old.json");
  EXPECT_EQ(b.findings.size(), 8u);  // separated pairs are no findings
  const RunResult run =
      run_with({pair(0, 1, Status::kInterference, 1.001), pair(1, 2, Status::kInterference, 1.5),
                pair(0, 2, Status::kInterference, 0.2), pair(0, 3, Status::kSeparated),
                pair(1, 3, Status::kError), pair(2, 4, Status::kInterference, 0.3)});
  ReviewOptions opt;
  opt.baseline = &b;
  opt.tolerance = 0.1;
  const Review rv = review_run(run, opt, false);
  auto state = [&](size_t k) { return baseline_state_name(*rv.pairs[k].baseline_state); };
  EXPECT_STREQ(state(0), "unchanged");
  EXPECT_STREQ(state(1), "updated");
  EXPECT_STREQ(state(2), "updated");
  EXPECT_FALSE(rv.pairs[3].baseline_state);  // clean pairs have no state
  EXPECT_FALSE(rv.pairs[4].baseline_state);
  EXPECT_STREQ(state(5), "new");
  std::map<std::string, std::string> gone;
  for (const auto& g : rv.gone)
    gone[g.was.a + "/" + g.was.b] = std::string(baseline_state_name(g.state)) + ": " + g.reason;
  EXPECT_EQ(gone.size(), 5u);
  EXPECT_EQ(gone.at("p0/p3"), "absent: checked: separated");
  EXPECT_EQ(gone.at("p0/p4").rfind("absent: checked: culled", 0), 0u) << gone.at("p0/p4");
  EXPECT_EQ(gone.at("p3/p5"), "unknown: part \"p5\" failed to load: unreadable");
  EXPECT_EQ(gone.at("p1/p3"), "unknown: the pair failed: worker crashed");
  EXPECT_EQ(gone.at("p0/gone"), "unknown: part \"gone\" is not in the scene");
  EXPECT_EQ(rv.state_count[static_cast<int>(BaselineState::kNew)], 1);
  EXPECT_EQ(rv.state_count[static_cast<int>(BaselineState::kUnchanged)], 1);
  EXPECT_EQ(rv.state_count[static_cast<int>(BaselineState::kUpdated)], 2);
  EXPECT_EQ(rv.state_count[static_cast<int>(BaselineState::kAbsent)], 2);
  EXPECT_EQ(rv.state_count[static_cast<int>(BaselineState::kUnknown)], 3);

  // A scene with a pair list: a baseline pair outside it was not checked.
  ReviewOptions listed = opt;
  listed.listed = std::set<std::string>{pair_fingerprint("p0", "p3")};
  for (const auto& g : review_run(run, listed, false).gone)
    if (g.was.a == "p0" && g.was.b == "p4") {
      EXPECT_EQ(g.state, BaselineState::kUnknown);
      EXPECT_NE(g.reason.find("not checked"), std::string::npos);
    }
}

TEST(Baseline, UpdatedNeedsAMaterialDepthChange) {
  const BaselineFinding old{"a", "b", "", "interference", 10.0};
  const double tol = 0.1;
  // Material: more than max(kBaselineDepthAbs·tol, kBaselineDepthRel·10) = 0.5.
  const double bound = std::max(tol::kBaselineDepthAbs * tol, tol::kBaselineDepthRel * 10.0);
  EXPECT_EQ(compare_finding(&old, Status::kInterference, 10.0 + 0.99 * bound, tol),
            BaselineState::kUnchanged);
  EXPECT_EQ(compare_finding(&old, Status::kInterference, 10.0 - 1.01 * bound, tol),
            BaselineState::kUpdated);
  const BaselineFinding shallow{"a", "b", "", "interference", 0.2};  // the absolute half rules
  EXPECT_EQ(compare_finding(&shallow, Status::kInterference, 0.2 + 0.009, tol),
            BaselineState::kUnchanged);
  EXPECT_EQ(compare_finding(&shallow, Status::kInterference, 0.2 + 0.011, tol),
            BaselineState::kUpdated);
  EXPECT_EQ(compare_finding(&old, Status::kClearanceViolation, 10.0, tol), BaselineState::kUpdated);
  EXPECT_EQ(compare_finding(nullptr, Status::kFalsePositive, 0.01, tol), BaselineState::kNew);
}

TEST(Baseline, MalformedFilesNameTheJsonPath) {
  auto err = [](const std::string& text) {
    return input_error_of([&] { parse_baseline(text, "old.json"); });
  };
  EXPECT_EQ(err("{\"pairs\": [\n  {\"a\": 1"), "old.json:2:10: invalid JSON");
  EXPECT_EQ(err("[]"), "old.json: $: must be an object");
  EXPECT_EQ(err(R"({"summary": {}})"),
            "old.json: $: a JSON Lines summary is not a baseline: use a --format json report");
  EXPECT_EQ(err(baseline_text(finding("a", "b", "interference", 1) + R"(, {"a": "c", "b": "d"})")),
            "old.json: $.pairs[1]: missing required key \"status\"");
  EXPECT_EQ(err(baseline_text(R"({"a": "c", "b": "d", "status": "bad"})")),
            "old.json: $.pairs[0].status: unknown status \"bad\"");
  EXPECT_EQ(err(baseline_text(R"({"a": "c", "b": "d", "status": "interference", "depth": "1"})")),
            "old.json: $.pairs[0].depth: must be a number");
  EXPECT_EQ(err(baseline_text(R"({"a": "c", "b": "d", "status": "interference", "depth": 1,
                                  "fingerprint": "00000000000000000000000000000000"})")),
            "old.json: $.pairs[0].fingerprint: does not match the ids (the report was edited, "
            "or is not pdcheck's)");
  EXPECT_EQ(err(baseline_text(finding("a", "b", "interference", 1) + "," +
                              finding("b", "a", "interference", 1))),
            "old.json: $.pairs[1]: the pair b / a appears twice");
}
}  // namespace pd
