// Baseline comparison, suppression matching and the --fail-on bar as pure
// functions on hand-built runs (the CLI tests run them end to end).
#include <gtest/gtest.h>

#include "report/baseline.h"
#include "report/input_error.h"
#include "report/review.h"
#include "report/suppressions.h"
#include "results/fingerprint.h"
#include "tolerances.h"

namespace pd {

namespace {

Part part(const std::string& id, std::optional<std::string> error = std::nullopt) {
  Part p;
  p.id = id;
  p.source = "inline";
  p.error = error;
  return p;
}

PairResult pair(int a, int b, Status s, double depth = 0.0) {
  PairResult r;
  r.a = a;
  r.b = b;
  r.status = s;
  r.depth = depth;
  if (s == Status::kError) r.error = "worker crashed";
  return r;
}

// Parts p0 … p5; p5 failed to load.
RunResult run_with(std::vector<PairResult> pairs) {
  RunResult r;
  for (int k = 0; k < 5; ++k) r.parts.push_back(part("p" + std::to_string(k)));
  r.parts.push_back(part("p5", "unreadable"));
  r.pairs = std::move(pairs);
  r.simulated = {"interference"};
  return r;
}

std::string baseline_text(const std::string& pairs) {
  return R"({"tool": {"name": "pdcheck"}, "pairs": [)" + pairs + "]}";
}

std::string finding(const std::string& a, const std::string& b, const std::string& status,
                    double depth) {
  return R"({"a": ")" + a + R"(", "b": ")" + b + R"(", "status": ")" + status + R"(", "depth": )" +
         std::to_string(depth) + "}";
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ReportInputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

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
    return error_of([&] { parse_baseline(text, "old.json"); });
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

TEST(Suppressions, ParsedWithTheirFields) {
  const Suppressions s = parse_suppressions(R"({"version": 1, "suppressions": [
    {"a": "p0", "b": "p1", "reason": "press fit", "owner": "jo", "expires": "2030-02-28",
     "max_depth": 0.5, "comment": "x"}]})",
                                            "s.json");
  ASSERT_EQ(s.entries.size(), 1u);
  EXPECT_EQ(s.entries[0].reason, "press fit");
  EXPECT_EQ(s.entries[0].owner, "jo");
  EXPECT_EQ(s.entries[0].expires, "2030-02-28");
  EXPECT_EQ(*s.entries[0].max_depth, 0.5);
  EXPECT_EQ(s.by_fingerprint.at(pair_fingerprint("p1", "p0")), 0u);
}

TEST(Suppressions, MalformedFilesNameTheJsonPath) {
  auto err = [](const std::string& entries) {
    return error_of(
        [&] { parse_suppressions(R"({"suppressions": [)" + entries + "]}", "s.json"); });
  };
  EXPECT_EQ(err(R"({"a": "x", "b": "y"})"),
            "s.json: $.suppressions[0]: missing required key \"reason\"");
  EXPECT_EQ(err(R"({"a": "x", "b": "y", "reason": " "})"),
            "s.json: $.suppressions[0].reason: must say why the finding is accepted (a non-empty "
            "string)");
  EXPECT_EQ(err(R"({"a": "x", "b": "y", "reason": "r", "expires": "2026-02-30"})"),
            "s.json: $.suppressions[0].expires: must be a date YYYY-MM-DD");
  EXPECT_EQ(err(R"({"a": "x", "b": "y", "reason": "r", "max_depth": -1})"),
            "s.json: $.suppressions[0].max_depth: must be a finite number >= 0");
  EXPECT_EQ(err(R"({"a": "x*", "b": "y", "reason": "r", "glob": true})"),
            "s.json: $.suppressions[0].glob: unknown key");
  EXPECT_EQ(err(R"({"a": "x", "b": "x", "reason": "r"})"),
            "s.json: $.suppressions[0].b: a part cannot be paired with itself");
  EXPECT_EQ(err(R"({"a": "x", "b": "y", "reason": "r"}, {"a": "y", "b": "x", "reason": "r"})"),
            "s.json: $.suppressions[1]: the pair y / x is already suppressed at "
            "$.suppressions[0]");
  EXPECT_EQ(error_of([] { parse_suppressions(R"({"suppresions": []})", "s.json"); }),
            "s.json: $.suppresions: unknown key");
}

TEST(Suppressions, Dates) {
  EXPECT_TRUE(is_iso_date("2024-02-29"));
  EXPECT_FALSE(is_iso_date("2023-02-29"));
  EXPECT_FALSE(is_iso_date("1900-02-29"));
  EXPECT_TRUE(is_iso_date("2000-02-29"));
  EXPECT_FALSE(is_iso_date("2024-13-01"));
  EXPECT_FALSE(is_iso_date("2024-1-01"));
  EXPECT_FALSE(is_iso_date("2024-01-01x"));
  EXPECT_TRUE(is_iso_date(utc_today()));
}

TEST(Suppressions, MatchStaleExpiredExceeded) {
  const Suppressions s = parse_suppressions(R"({"suppressions": [
    {"a": "p0", "b": "p1", "reason": "press fit", "max_depth": 1.5},
    {"a": "p1", "b": "p2", "reason": "known, ECO-7", "max_depth": 0.5},
    {"a": "p0", "b": "p2", "reason": "until the redesign", "expires": "2026-01-31"},
    {"a": "p0", "b": "p3", "reason": "fixed since"},
    {"a": "p3", "b": "p5", "reason": "part p5 failed"}]})",
                                            "s.json");
  const RunResult run =
      run_with({pair(0, 1, Status::kInterference, 1.0), pair(1, 2, Status::kInterference, 0.7),
                pair(0, 2, Status::kInterference, 0.2), pair(0, 3, Status::kSeparated)});
  ReviewOptions opt;
  opt.suppressions = &s;
  opt.units = "in";
  opt.today = "2026-01-31";  // the last day p0/p2 holds
  Review rv = review_run(run, opt, false);
  EXPECT_TRUE(rv.pairs[0].suppressed);
  EXPECT_FALSE(rv.pairs[0].fails);
  EXPECT_FALSE(rv.pairs[1].suppressed);  // deeper than max_depth: no longer held
  EXPECT_EQ(rv.pairs[1].not_holding, Hold::kExceeded);
  EXPECT_TRUE(rv.pairs[1].fails);
  EXPECT_TRUE(rv.pairs[2].suppressed);
  EXPECT_EQ(rv.suppressed, 2);
  std::map<std::string, std::string> issues;
  for (const auto& i : rv.suppression_issues)
    issues[i.entry->a + "/" + i.entry->b] = i.kind + (i.fails ? " fails" : "");
  EXPECT_EQ(issues,
            (std::map<std::string, std::string>{
                {"p1/p2", "exceeded"}, {"p0/p3", "unmatched fails"}, {"p3/p5", "unchecked"}}));
  for (const auto& i : rv.suppression_issues)  // every length with its unit
    if (i.kind == "exceeded") {
      EXPECT_EQ(i.detail,
                "depth 0.7 in exceeds max_depth 0.5 in; the finding is reported as if "
                "unsuppressed");
    }
  EXPECT_EQ(rv.exit_code, 1);

  opt.today = "2026-02-01";  // the day after: expired, and the finding fails again
  rv = review_run(run, opt, false);
  EXPECT_FALSE(rv.pairs[2].suppressed);
  EXPECT_TRUE(rv.pairs[2].fails);
  bool expired = false;
  for (const auto& i : rv.suppression_issues) expired |= i.kind == "expired" && i.fails;
  EXPECT_TRUE(expired);

  // Stale entries alone fail the run unless allowed.
  const RunResult clean = run_with({pair(0, 1, Status::kInterference, 1.0)});
  const Suppressions one_stale = parse_suppressions(R"({"suppressions": [
    {"a": "p0", "b": "p1", "reason": "press fit"}, {"a": "p0", "b": "p4", "reason": "gone"}]})",
                                                    "s.json");
  opt.suppressions = &one_stale;
  EXPECT_EQ(review_run(clean, opt, false).exit_code, 1);
  opt.allow_stale = true;
  EXPECT_EQ(review_run(clean, opt, false).exit_code, 0);
  EXPECT_EQ(review_run(clean, opt, true).exit_code, 3);  // incomplete wins
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
