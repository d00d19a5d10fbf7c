// The review in the JSON reports (review_json.cpp): each pair's baseline state,
// suppression and group, and the run's counts and sections.
#include <gtest/gtest.h>

#include "report/baseline.h"
#include "report/review_json.h"
#include "report/suppressions.h"
#include "report_fixture.h"
#include "results/fingerprint.h"

using namespace pd;
using namespace pd::test;
using ojson = nlohmann::ordered_json;

namespace {

/// The fixture's run reviewed against a baseline that knew frame / pin as an
/// interference and a gone pair, and a suppression of lid / pin.
struct Reviewed {
  ReportFixture f = every_status();
  Baseline baseline = parse_baseline(
      R"({"pairs": [{"a": "frame", "b": "pin", "status": "interference", "depth": 0.5},
                    {"a": "old", "b": "gone", "status": "interference", "depth": 2}]})",
      "old.json");
  Suppressions suppressions = parse_suppressions(
      R"({"suppressions": [{"a": "lid <&>", "b": "pin", "reason": "press fit", "owner": "kim",
                            "max_depth": 0.5}]})",
      "sup.json");
  Reviewed() {
    f.options.baseline = &baseline;
    f.options.suppressions = &suppressions;
    f.input();
  }
};

}  // namespace

TEST(ReviewJson, PairsCarryTheirStateSuppressionAndGroup) {
  Reviewed r;
  const Review& rv = r.f.review;
  ojson lid = {{"a", "frame"}, {"group", "stale"}};
  add_pair_review(lid, rv.pairs[0]);
  EXPECT_EQ(lid["baseline_state"], "new");
  EXPECT_FALSE(lid.contains("suppressed"));
  ojson pin = ojson::object();
  add_pair_review(pin, rv.pairs[3]);  // lid / pin: suppressed, as its entry says
  EXPECT_EQ(pin["suppressed"],
            ojson({{"reason", "press fit"}, {"owner", "kim"}, {"max_depth", 0.5}}));
  ojson fp = ojson::object();
  add_pair_review(fp, rv.pairs[1]);  // frame / pin: an interference before, a false positive now
  EXPECT_EQ(fp["baseline_state"], "updated");
  // A group is set when the review found one, and cleared when not (a shard's
  // own group does not survive a merge's review).
  ojson clean = {{"group", "from a shard"}};
  add_pair_review(clean, rv.pairs[2]);
  EXPECT_FALSE(clean.contains("group"));
  EXPECT_FALSE(clean.contains("baseline_state"));  // separated: no finding, no state
}

TEST(ReviewJson, TheRunsCountsAndSections) {
  Reviewed r;
  ojson doc = ojson::object();
  ojson summary = {{"exit_code", 0}};
  add_run_review(doc, summary, r.f.review, r.f.options);
  EXPECT_EQ(summary["fail_on"], "interference");
  EXPECT_EQ(summary["failing"], 1);  // frame / lid; lid / pin is suppressed
  EXPECT_EQ(summary["suppressed"], 1);
  EXPECT_EQ(summary["exit_code"], 3);        // the review's, over the summary's own
  EXPECT_EQ(summary["baseline"]["new"], 2);  // frame / lid, lid / pin
  EXPECT_EQ(summary["baseline"]["updated"], 1);
  EXPECT_EQ(doc["baseline"]["file"], "old.json");
  ASSERT_EQ(doc["baseline"]["gone"].size(), 1u);
  EXPECT_EQ(doc["baseline"]["gone"][0]["a"], "old");
  EXPECT_EQ(doc["baseline"]["gone"][0]["status_was"], "interference");
  EXPECT_EQ(doc["baseline"]["gone"][0]["fingerprint"], pair_fingerprint("old", "gone"));
  EXPECT_EQ(doc["suppressions"]["file"], "sup.json");
  EXPECT_TRUE(doc["suppressions"]["issues"].empty());
  // Without either file: neither section, no suppressed count.
  ReportFixture plain = every_status();
  plain.input();
  ojson doc2 = ojson::object(), summary2 = ojson::object();
  add_run_review(doc2, summary2, plain.review, plain.options);
  EXPECT_TRUE(doc2.empty());
  EXPECT_FALSE(summary2.contains("suppressed"));
  EXPECT_FALSE(summary2.contains("baseline"));
}
