// Expected-contact rules as the review sees them (expected_rules.cpp): one
// suppression per rule, read from the rules or from a report's section.
#include <gtest/gtest.h>

#include "report/expected_rules.h"
#include "report/input_error.h"
#include "scene/rules.h"

using namespace pd;

TEST(ExpectedRules, OneSuppressionPerRuleByName) {
  Rules rules;
  ExpectedRule press;
  press.name = "press fits";
  press.reason = "bushings are pressed in";
  press.max_depth = 0.5;
  press.where = "rules.expected[0]";
  ExpectedRule snap = press;
  snap.name = "snaps";
  snap.max_depth = 0.2;
  snap.where = "rules.expected[1]";
  rules.expected = {press, snap};
  const ExpectedRules e = expected_rules_of(rules);
  ASSERT_EQ(e.entries.size(), 2u);
  EXPECT_EQ(e.by_name.at("press fits"), 0u);
  EXPECT_EQ(e.by_name.at("snaps"), 1u);
  EXPECT_EQ(e.entries[1].rule, "snaps");
  EXPECT_EQ(e.entries[1].reason, "bushings are pressed in");
  EXPECT_EQ(e.entries[1].max_depth, 0.2);
  EXPECT_EQ(suppression_origin(e.entries[0], "sup.json"),
            "expected-contact rule \"press fits\", rules.expected[0]");
  Suppression entry;
  entry.where = "$.suppressions[2]";
  EXPECT_EQ(suppression_origin(entry, "sup.json"), "sup.json $.suppressions[2]");
}

TEST(ExpectedRules, FromAReportSection) {
  const auto section = nlohmann::ordered_json::parse(
      R"({"expected": [{"name": "press fits", "reason": "r", "max_depth": 0.5, "where": "w"},
                       {"name": "snaps", "reason": "s", "max_depth": 0.2}]})");
  const ExpectedRules e = expected_rules_of_report(section, "shard1.json");
  ASSERT_EQ(e.entries.size(), 2u);
  EXPECT_EQ(e.entries[0].where, "w");
  EXPECT_EQ(e.entries[1].where, "");
  EXPECT_EQ(e.entries[1].max_depth, 0.2);
  EXPECT_TRUE(expected_rules_of_report(nlohmann::ordered_json::object(), "x").entries.empty());
  EXPECT_TRUE(expected_rules_of_report(nullptr, "x").entries.empty());
  const auto bad = nlohmann::ordered_json::parse(R"({"expected": [{"name": "n", "reason": "r"}]})");
  try {
    expected_rules_of_report(bad, "shard1.json");
    ADD_FAILURE() << "an entry without max_depth was read";
  } catch (const ReportInputError& ex) {
    EXPECT_EQ(std::string(ex.what()).rfind("shard1.json: $.rules.expected: ", 0), 0u) << ex.what();
  }
}
