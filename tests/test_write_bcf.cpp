// The BCF export (--bcf, write_bcf.cpp) in process: every file of the zip
// validated against buildingSMART's BCF 3.0 schemas (tests/bcf_check.h).
// Through the binary, against the JSON report and a merge: test_exports.cpp.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "bcf_check.h"
#include "report/bcf_topics.h"
#include "report_fixture.h"

using namespace pd::test;

namespace {

/// A number as the JSON report's text has it.
std::string number_text(double x) {
  return nlohmann::json(x).dump();
}

}  // namespace

// In process: every status through the BCF writer, each file valid; the
// topics are exactly the pairs that need a person.
TEST(WriteBcf, EveryStatusGivesAValidBcf) {
  ReportFixture f("in");
  for (const std::string id : {"a <&>", "b", "c", "d", "e", "f", "g"}) f.part(id);
  const pd::Status statuses[] = {pd::Status::kSeparated,    pd::Status::kFalsePositive,
                                 pd::Status::kInterference, pd::Status::kClearanceViolation,
                                 pd::Status::kUndecided,    pd::Status::kError};
  for (int k = 0; k < 6; ++k) {
    pd::PairResult& r = f.pair(k, k + 1, statuses[k], k == 3 ? 0.0 : 0.02 * k);
    r.direction = pd::Vec3(0, 0, k % 2 ? 1 : -1);
    if (r.status == pd::Status::kClearanceViolation) {
      r.clearance_min = 0.5;
      r.distance = 0.2;
    }
    if (r.status == pd::Status::kUndecided) {
      r.depth_bounds = std::array<double, 2>{0.05, 0.2};
      r.reason = "work box exhausted";
      r.depth_source = "thickness";
      r.at = pd::Vec3(13.5, 0.5, 0.5);
    }
    if (r.status == pd::Status::kError) r.error = "worker timed out";
  }
  const pd::ReportInput in = f.input();
  const pd::Review& review = f.review;
  const std::string path = process_temp("exports_statuses.bcf");
  std::ofstream(path, std::ios::binary) << pd::render_bcf(in);
  const std::string dir = process_temp("exports_statuses");
  const std::vector<std::string> topics = check_bcf(path, dir);
  // The interference (c, d) and the clearance violation (d, e) both move d
  // along −z: one finding group, one topic keyed by the group's id, its
  // deepest member (the interference) first. Then the undecided and the error.
  ASSERT_EQ(review.groups.groups.size(), 1u);
  const pd::FindingGroup& group = review.groups.groups[0];
  EXPECT_EQ(group.members, (std::vector<size_t>{2, 3}));
  std::vector<std::string> want{pd::bcf_guid("topic", group.id)};
  for (int k = 4; k < 6; ++k) want.push_back(pd::bcf_guid("topic", review.pairs[k].fingerprint));
  EXPECT_EQ(topics, want);
  if (topics.size() != 3) return;
  for (const auto& [k, type] : std::vector<std::pair<int, std::string>>{
           {0, "Interference"}, {1, "Undecided"}, {2, "Not checked"}})
    EXPECT_NE(read_text(dir + "/" + topics[k] + "/markup.bcf").find("TopicType=\"" + type + "\""),
              std::string::npos)
        << type;
  const std::string grouped = read_text(dir + "/" + topics[0] + "/markup.bcf");
  EXPECT_NE(grouped.find("(and 1 more)"), std::string::npos) << grouped;
  EXPECT_NE(grouped.find("<Label>clearance_violation</Label>"), std::string::npos) << grouped;
  EXPECT_NE(grouped.find("group " + group.id), std::string::npos) << grouped;
  // The undecided pair has an `at`: its line starts there, in metres (inches * 0.0254).
  const std::string v = read_text(dir + "/" + topics[1] + "/viewpoint.bcfv");
  EXPECT_NE(v.find("<StartPoint>\n        <X>" + number_text(13.5 * (25.4 / 1000.0)) + "</X>"),
            std::string::npos)
      << v;
  EXPECT_NE(read_text(dir + "/" + topics[0] + "/viewpoint.bcfv")
                .find("<AuthoringToolId>c</AuthoringToolId>"),
            std::string::npos);
}
