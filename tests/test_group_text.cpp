// The finding groups on stderr (group_text.cpp): a line per group of several
// findings, at most ten, and nothing for a lone finding.
#include <gtest/gtest.h>

#include "bcf_check.h"
#include "report/group_text.h"
#include "report_fixture.h"

using namespace pd;
using namespace pd::test;

TEST(GroupText, ALinePerGroupOfSeveralFindings) {
  ReportFixture f = every_status();
  const ReportInput in = f.input();
  ASSERT_EQ(f.review.groups.groups.size(), 1u);
  const std::string id = f.review.groups.groups[0].id.substr(0, 8);
  EXPECT_EQ(group_lines(in), "pdcheck: group " + id +
                                 ": 2 findings (frame, lid <&>, pin): moving lid <&> by 1 mm "
                                 "along (0, 0, 1) clears 2 of them; deepest frame / lid <&>, "
                                 "depth 1 mm\n");
  // The deepest's depth is named for what it is.
  for (PairResult& r : f.run.pairs) r.depth_source = "thickness";
  EXPECT_NE(group_lines(f.input()).find("deepest frame / lid <&>, overlap thickness 1 mm"),
            std::string::npos)
      << group_lines(f.input());
  // One finding alone: its own finding line says it all.
  f.run.pairs.erase(f.run.pairs.begin() + 3);
  EXPECT_EQ(group_lines(f.input()), "");
}

TEST(GroupText, AtMostTenGroupsThenACount) {
  // 12 separate plates, each with two bolts pushed up out of it: 12 groups of two.
  ReportFixture f;
  for (int g = 0; g < 12; ++g) {
    const int plate = static_cast<int>(f.run.parts.size());
    f.part("plate" + std::to_string(g));
    f.part("bolt" + std::to_string(g) + "a");
    f.part("bolt" + std::to_string(g) + "b");
    f.pair(plate, plate + 1, Status::kInterference, 0.5 + g).direction = Vec3::UnitZ();
    f.pair(plate, plate + 2, Status::kInterference, 0.4 + g).direction = Vec3::UnitZ();
  }
  const std::string text = group_lines(f.input());
  EXPECT_EQ(count_of(text, "pdcheck: group "), 10u) << text;
  EXPECT_NE(text.find("pdcheck: … and 2 more groups of several findings"), std::string::npos)
      << text;
  // The deepest groups first: the two shallowest are the ones left out.
  EXPECT_LT(text.find("plate11)"), text.find("plate10)")) << text;
  EXPECT_EQ(text.find("plate0)"), std::string::npos) << text;
  EXPECT_EQ(text.find("plate1)"), std::string::npos) << text;
}
