// Finding groups (report/finding_groups.h) as a pure function on hand-built
// results, and in the report (review, JSON, stderr lines).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "report/finding_groups.h"
#include "report/group_text.h"
#include "report/review.h"
#include "report/writer.h"
#include "results/fingerprint.h"
#include "tolerances.h"

namespace pd {

namespace {

PairResult finding(int a, int b, Status s, double depth, const Vec3& direction) {
  PairResult r;
  r.a = a;
  r.b = b;
  r.status = s;
  r.depth = depth;
  r.direction = direction.normalized();
  return r;
}

// The same finding with a and b swapped: the same pair, the same move of each part.
PairResult swapped(PairResult r) {
  std::swap(r.a, r.b);
  r.direction = -r.direction;
  return r;
}

const std::vector<std::string> kIds = {"plate", "bolt-1", "bolt-2", "bolt-3", "wall", "pin"};

// The plate (0) sits too low into three bolts: each finding asks the plate to
// move down (within 6° of −z; the plate is b in two of them, a in one), and
// into the wall, which asks it to move along +x: the bolts are one fix.
std::vector<PairResult> plate_case() {
  return {finding(1, 0, Status::kInterference, 0.4, Vec3(0, 0, -1)),
          finding(0, 2, Status::kInterference, 0.3, Vec3(0, 0.1, 1)),
          finding(3, 0, Status::kInterference, 0.35, Vec3(0.05, 0, -1)),
          finding(4, 0, Status::kInterference, 0.2, Vec3(1, 0, 0)),
          finding(4, 5, Status::kFalsePositive, 0.01, Vec3(1, 0, 0)),
          finding(2, 5, Status::kUndecided, 0.2, Vec3(0, 1, 0))};
}

}  // namespace

TEST(FindingGroups, MovesOfASharedPartWithinTheAngleAreOneGroup) {
  const std::vector<PairResult> pairs = plate_case();
  for (size_t k : {0, 1, 2}) EXPECT_LT(move_of(pairs[k], 0).z(), -0.9) << k;
  const FindingGroups g = group_findings(pairs, kIds);
  ASSERT_EQ(g.groups.size(), 2u);
  // The deepest group first: the three bolts, deepest bolt-1 / plate.
  EXPECT_EQ(g.groups[0].members, (std::vector<size_t>{0, 1, 2}));
  EXPECT_EQ(g.groups[0].deepest, 0u);
  EXPECT_EQ(g.groups[1].members, (std::vector<size_t>{3}));
  EXPECT_EQ(g.group_of, (std::vector<int>{0, 0, 0, 1, -1, -1}));  // no fix needed: no group
  // The fix: move the plate (in every member) along their mean move, far enough
  // for each (depth / cosine to the mean).
  const SuggestedMove& m = g.groups[0].move;
  EXPECT_EQ(m.part, 0);
  EXPECT_EQ(m.covers.size(), 3u);
  EXPECT_LT(m.direction.z(), -0.99);
  double need = 0;
  for (size_t k : {0, 1, 2})
    need = std::max(need, pairs[k].depth / m.direction.dot(move_of(pairs[k], 0)));
  EXPECT_DOUBLE_EQ(m.length, need);
  EXPECT_GE(m.length, 0.4);
  EXPECT_EQ(g.groups[0].parts, (std::vector<int>{1, 2, 3, 0}));  // by id: bolt-1 … plate
}

TEST(FindingGroups, TheAngleDecides) {
  // Two findings of part 0, moves 29° and 31° apart.
  for (double deg : {29.0, 31.0}) {
    const double t = deg * M_PI / 180;
    const std::vector<PairResult> pairs = {
        finding(1, 0, Status::kInterference, 0.2, Vec3(1, 0, 0)),
        finding(2, 0, Status::kClearanceViolation, 0.0, Vec3(std::cos(t), std::sin(t), 0))};
    const FindingGroups g = group_findings(pairs, kIds);
    EXPECT_EQ(g.groups.size(), deg < tol::kGroupMoveAngle * 180 / M_PI ? 1u : 2u) << deg;
  }
}

TEST(FindingGroups, IdsDependOnTheMembersAloneAndTheDeepestLeads) {
  std::vector<PairResult> pairs = {finding(1, 0, Status::kInterference, 0.2, Vec3(0, 0, 1)),
                                   finding(2, 0, Status::kInterference, 0.5, Vec3(0, 0.2, 1)),
                                   finding(4, 5, Status::kInterference, 0.3, Vec3(1, 0, 0))};
  const FindingGroups g = group_findings(pairs, kIds);
  ASSERT_EQ(g.groups.size(), 2u);
  EXPECT_EQ(g.groups[0].deepest, 1u);
  EXPECT_EQ(g.groups[0].id.size(), 32u);
  EXPECT_NE(g.groups[0].id, g.groups[1].id);
  // Another order, a and b swapped, other part indices (ids permuted with them):
  // the same groups with the same ids.
  std::vector<std::string> ids = {"pin", "wall", "plate", "bolt-1", "bolt-2", "bolt-3"};
  const auto index = [&](int k) {
    return int(std::find(ids.begin(), ids.end(), kIds[k]) - ids.begin());
  };
  std::vector<PairResult> moved;
  for (auto it = pairs.rbegin(); it != pairs.rend(); ++it) {
    PairResult r = swapped(*it);
    r.a = index(r.a), r.b = index(r.b);
    moved.push_back(r);
  }
  const FindingGroups h = group_findings(moved, ids);
  ASSERT_EQ(h.groups.size(), 2u);
  for (size_t n = 0; n < 2; ++n) {
    EXPECT_EQ(h.groups[n].id, g.groups[n].id);
    EXPECT_EQ(h.groups[n].members.size(), g.groups[n].members.size());
  }
  // A member more is another group.
  pairs.push_back(finding(3, 0, Status::kInterference, 0.1, Vec3(0, 0, 1)));
  EXPECT_NE(group_findings(pairs, kIds).groups[0].id, g.groups[0].id);
}

TEST(FindingGroups, ClearanceShortfallSizesTheMove) {
  PairResult c = finding(0, 1, Status::kClearanceViolation, 0.0, Vec3(1, 0, 0));
  c.clearance_min = 0.5;
  c.distance = 0.2;
  const FindingGroups g = group_findings({c}, kIds);
  ASSERT_EQ(g.groups.size(), 1u);
  EXPECT_NEAR(g.groups[0].move.length, 0.3, 1e-15);
  // bolt-1 < plate bytewise: the move is bolt-1's (b), along +x.
  EXPECT_EQ(g.groups[0].move.part, 1);
  EXPECT_EQ(g.groups[0].move.direction, Vec3(1, 0, 0));
  // Overlapping by 0.02 within the tolerance: out of the overlap, then the clearance.
  PairResult press = finding(0, 1, Status::kClearanceViolation, 0.02, Vec3(1, 0, 0));
  press.clearance_min = 0.5;
  EXPECT_NEAR(group_findings({press}, kIds).groups[0].move.length, 0.52, 1e-15);
}

TEST(FindingGroups, InTheReportAndOnStderr) {
  RunResult run;
  for (const std::string& id : kIds) {
    Part p;
    p.id = id;
    p.source = "inline";
    run.parts.push_back(p);
  }
  run.simulated = {"interference"};
  run.pairs = {finding(1, 0, Status::kInterference, 0.4, Vec3(0, 0, 1)),
               finding(2, 0, Status::kInterference, 0.3, Vec3(0, 0, 1)),
               finding(4, 5, Status::kFalsePositive, 0.01, Vec3(1, 0, 0))};
  run.pairs[0].at = Vec3(1, 2, 3);
  const ReviewOptions opt;
  const Review rv = review_run(run, opt, false);
  ReportContext ctx;
  ctx.units = "mm";
  ctx.tolerance = 0.1;
  const ReportInput in{ctx, run, rv, opt};
  const nlohmann::ordered_json doc = report_document(in);
  ASSERT_EQ(doc["groups"].size(), 1u);
  const auto& g = doc["groups"][0];
  EXPECT_EQ(doc["pairs"][0]["group"], g["id"]);
  EXPECT_EQ(doc["pairs"][1]["group"], g["id"]);
  EXPECT_FALSE(doc["pairs"][2].contains("group"));
  EXPECT_EQ(doc["pairs"][0]["at"], nlohmann::ordered_json::array({1.0, 2.0, 3.0}));
  EXPECT_EQ(g["deepest"], pair_fingerprint("bolt-1", "plate"));
  EXPECT_EQ(g["members"].size(), 2u);
  EXPECT_EQ(g["members"][1]["a"], "bolt-2");
  EXPECT_EQ(g["parts"], nlohmann::ordered_json::array({"bolt-1", "bolt-2", "plate"}));
  EXPECT_EQ(g["move"]["part"], "plate");
  EXPECT_EQ(g["move"]["direction"], nlohmann::ordered_json::array({0.0, 0.0, 1.0}));
  EXPECT_DOUBLE_EQ(g["move"]["length"].get<double>(), 0.4);
  const std::string lines = group_lines(in);
  EXPECT_EQ(lines, "pdcheck: group " + g["id"].get<std::string>().substr(0, 8) +
                       ": 2 findings (bolt-1, bolt-2, plate): moving plate by 0.4 mm along (0, 0, "
                       "1) clears 2 of them; deepest bolt-1 / plate, depth 0.4 mm\n");
}

}  // namespace pd
