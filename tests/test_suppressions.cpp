// The suppressions file (suppressions.cpp): its fields, dates, malformed files
// named by their JSON path, and which entries match, go stale or are exceeded.
#include <gtest/gtest.h>

#include "report/review.h"
#include "report/suppressions.h"
#include "results/fingerprint.h"
#include "review_runs.h"
#include "tolerances.h"

namespace pd {

using namespace pd::test;

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
    return input_error_of(
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
  EXPECT_EQ(input_error_of([] { parse_suppressions(R"({"suppresions": []})", "s.json"); }),
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
}  // namespace pd
