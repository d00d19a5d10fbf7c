// The report's `groups` (groups_json.cpp): each finding group with its members,
// parts, deepest member and suggested move, named by ids and fingerprints.
#include <gtest/gtest.h>

#include "report/groups_json.h"
#include "report_fixture.h"
#include "results/fingerprint.h"

using namespace pd;
using namespace pd::test;
using json = nlohmann::ordered_json;

TEST(GroupsJson, MembersPartsDeepestAndMove) {
  ReportFixture f = every_status();
  f.input();
  const json groups = groups_json(f.review.groups, f.run);
  ASSERT_EQ(groups.size(), 1u) << groups.dump(1);
  const json& g = groups[0];
  EXPECT_EQ(g["id"], f.review.groups.groups[0].id);
  const std::string lid = pair_fingerprint("frame", "lid <&>"),
                    pin = pair_fingerprint("lid <&>", "pin");
  EXPECT_EQ(g["members"],
            json::parse(R"([{"fingerprint": ")" + lid +
                        R"(", "a": "frame", "b": "lid <&>", "status": "interference"},
                            {"fingerprint": ")" +
                        pin + R"(", "a": "lid <&>", "b": "pin", "status": "interference"}])"));
  EXPECT_EQ(g["parts"], json({"frame", "lid <&>", "pin"}));
  EXPECT_EQ(g["deepest"], lid);
  EXPECT_EQ(g["depth"], 1.0);
  EXPECT_EQ(g["depth_source"], "hull");
  // Both findings clear by moving the lid up, as far as the deeper one needs.
  EXPECT_EQ(g["move"]["part"], "lid <&>");
  EXPECT_EQ(g["move"]["direction"], json({0.0, 0.0, 1.0}));
  EXPECT_EQ(g["move"]["length"], 1.0);
  EXPECT_EQ(g["move"]["covers"], json({lid, pin}));
}

TEST(GroupsJson, NoFindingsNoGroups) {
  ReportFixture f;
  f.part("a");
  f.part("b");
  f.pair(0, 1, Status::kFalsePositive, 0.05);
  f.input();
  EXPECT_EQ(groups_json(f.review.groups, f.run), json::array());
}
