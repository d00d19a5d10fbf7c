// The report's `rules` section (rules_report.cpp) as a merge adds up its
// shards' sections: pair counts summed, everything else as one shard has it.
#include <gtest/gtest.h>

#include "report/rules_report.h"

using namespace pd;
using json = nlohmann::ordered_json;

namespace {

json section(long t0, long t1, long ig, long ex, long out_of_scope, long ignored) {
  return {{"source", "scene"},
          {"sets", {{{"name", "bolts"}, {"parts", 4}}}},
          {"tests", {{{"a", "bolts"}, {"b", "*"}, {"pairs", t0}}, {{"a", "x"}, {"pairs", t1}}}},
          {"ignore", {{{"same", "group"}, {"pairs", ig}}}},
          {"expected", {{{"name", "press"}, {"pairs", ex}}}},
          {"pairs", json::array()},
          {"out_of_scope", out_of_scope},
          {"ignored", ignored}};
}

}  // namespace

TEST(RulesReport, ShardSectionsAddUp) {
  const json a = section(3, 0, 1, 2, 5, 1), b = section(4, 2, 0, 1, 1, 0),
             c = section(0, 1, 2, 0, 0, 2);
  const json m = merge_rules_sections({&a, &b, &c});
  EXPECT_EQ(m["tests"][0]["pairs"], 7);
  EXPECT_EQ(m["tests"][1]["pairs"], 3);
  EXPECT_EQ(m["ignore"][0]["pairs"], 3);
  EXPECT_EQ(m["expected"][0]["pairs"], 3);
  EXPECT_EQ(m["out_of_scope"], 6);
  EXPECT_EQ(m["ignored"], 3);
  // What every shard resolves alike is the first one's: the rules and set coverage.
  EXPECT_EQ(m["sets"], a["sets"]);
  EXPECT_EQ(m["tests"][0]["a"], "bolts");
  EXPECT_EQ(m["source"], "scene");
  // The order of the shards does not matter.
  EXPECT_EQ(merge_rules_sections({&c, &a, &b}), m);
  // One shard: its own section.
  EXPECT_EQ(merge_rules_sections({&b}), b);
}
