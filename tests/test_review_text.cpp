// The review for people (review_text.cpp): stderr lines for failing findings,
// groups, suppressions and the baseline, and the --write-suppressions file.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "bcf_check.h"
#include "report/review_text.h"
#include "report/suppressions.h"
#include "report_fixture.h"

using namespace pd;
using namespace pd::test;

TEST(ReviewText, FailingFindingsThenTheGroup) {
  ReportFixture f = every_status();
  const std::string text = review_lines(f.input());
  EXPECT_EQ(count_of(text, "pdcheck: fails --fail-on interference: "), 2u) << text;
  EXPECT_NE(text.find("fails --fail-on interference: frame / lid <&>: interference"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("frame / pin"), std::string::npos) << "a false positive does not fail";
  EXPECT_EQ(count_of(text, "pdcheck: group "), 1u) << text;
  EXPECT_EQ(text.find("suppressions"), std::string::npos);
  EXPECT_EQ(text.find("baseline"), std::string::npos);
}

TEST(ReviewText, AtMostTwentyFailingFindings) {
  ReportFixture f;
  for (int k = 0; k < 26; ++k) f.part("p" + std::to_string(k));
  for (int k = 0; k < 25; ++k)
    f.pair(k, k + 1, Status::kInterference, 1.0).direction =
        Vec3(std::cos(k), std::sin(k), 0.0);  // no two moves alike: no groups of several
  const std::string text = review_lines(f.input());
  EXPECT_EQ(count_of(text, "pdcheck: fails --fail-on"), 20u);
  EXPECT_NE(text.find("pdcheck: … and 5 more failing findings\n"), std::string::npos) << text;
}

TEST(ReviewText, SuppressionsFileKeepsEntriesAndListsFindingsAtTheBar) {
  ReportFixture f = every_status();
  const Suppressions current = parse_suppressions(
      R"({"suppressions": [{"a": "pin", "b": "lid <&>", "reason": "press fit", "owner": "kim"}]})",
      "sup.json");
  f.options.suppressions = &current;
  const ReportInput in = f.input();
  const std::string text = suppressions_to_write(in, "2024-05-01");
  const nlohmann::json doc = nlohmann::json::parse(text);
  const nlohmann::json& entries = doc["suppressions"];
  ASSERT_EQ(entries.size(), 2u) << text;  // the two interferences, not the false positive
  EXPECT_EQ(entries[0]["a"], "frame");
  EXPECT_EQ(entries[0]["b"], "lid <&>");
  EXPECT_EQ(entries[1]["reason"], "press fit");  // the reviewed entry, as it was
  EXPECT_EQ(entries[1]["owner"], "kim");
  // The new entry is rejected until a person gives a reason.
  EXPECT_THROW(parse_suppressions(text, "new.json"), std::exception);
  // The file lists what review_lines reported: the suppressed pair no longer fails.
  EXPECT_EQ(count_of(review_lines(in), "pdcheck: fails --fail-on"), 1u);
  EXPECT_NE(review_lines(in).find("pdcheck: suppressions sup.json: 1 finding(s) suppressed"),
            std::string::npos);
}
