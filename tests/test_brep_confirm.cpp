// batch/brep_confirm.h: the pure steps (the bracket, its certification by the
// deflection bound, the decision on the solids' measurements), then the whole
// pipeline on STEP assemblies made with Open CASCADE (tests/brep_cases.h),
// every nominal relation known by construction.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "batch/brep_confirm.h"
#include "brep/exact_pair.h"
#include "brep_cases.h"
#include "cli_support.h"

namespace {

using pd::ExactBasis;
using pd::ExactContext;
using pd::ExactMeasure;
using pd::ExactVerdict;
using pd::PairResult;
using pd::Status;
using pd::Vec3;

PairResult result(Status s, double depth, std::optional<std::array<double, 2>> bounds = {}) {
  PairResult r;
  r.status = s;
  r.depth = depth;
  r.depth_bounds = bounds;
  r.depth_source = bounds ? "thickness" : "hull";
  return r;
}

ExactContext context(double tolerance, double sag, bool bounds = true) {
  ExactContext c;
  c.tolerance = tolerance;
  c.pair_size = 100.0;
  c.sag = sag;
  c.bounds = bounds;
  return c;
}

TEST(BrepConfirm, MeshBracketSaysWhatTheDepthBounds) {
  EXPECT_EQ(pd::mesh_bracket(result(Status::kSeparated, 0.0), true), (std::array{0.0, 0.0}));
  EXPECT_EQ(pd::mesh_bracket(result(Status::kInterference, 2.0), true), (std::array{2.0, 2.0}));
  // A hull depth over a nonconvex part bounds from above only.
  EXPECT_EQ(pd::mesh_bracket(result(Status::kFalsePositive, 0.02), false), (std::array{0.0, 0.02}));
  EXPECT_EQ(pd::mesh_bracket(result(Status::kInterference, 0.5, std::array{0.4, 0.6}), false),
            (std::array{0.4, 0.6}));
}

// The bracket widened by twice the larger sag decides, or nothing is certified.
TEST(BrepConfirm, TheBoundCertifiesOnlyWhatSurvivesTheWidening) {
  const ExactContext c = context(0.05, 0.01);
  // A press fit: the meshes overlap by at most 0.02; with the sags at most 0.04 ≤ 0.05.
  auto e = pd::certify_by_bound(result(Status::kFalsePositive, 0.02, std::array{0.01, 0.02}),
                                {0.01, 0.02}, c);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->verdict, ExactVerdict::kFalsePositive);
  EXPECT_EQ(e->basis, ExactBasis::kBound);
  EXPECT_DOUBLE_EQ((*e->depth_bounds)[1], 0.04);
  EXPECT_DOUBLE_EQ((*e->depth_bounds)[0], 0.0);
  // 0.035 + 0.02 > 0.05: the solids may overlap by more than the tolerance.
  EXPECT_FALSE(pd::certify_by_bound(result(Status::kFalsePositive, 0.035), {0.0, 0.035}, c));
  // An interference whose lower end keeps above the tolerance widened.
  e = pd::certify_by_bound(result(Status::kInterference, 1.0), {1.0, 1.0}, c);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->verdict, ExactVerdict::kInterference);
  EXPECT_DOUBLE_EQ((*e->depth_bounds)[0], 0.98);
  EXPECT_FALSE(pd::certify_by_bound(result(Status::kInterference, 0.065), {0.065, 0.065}, c));
  // Estimated sags certify nothing.
  EXPECT_FALSE(pd::certify_by_bound(result(Status::kInterference, 1.0), {1.0, 1.0},
                                    context(0.05, 0.01, false)));
  // Apart: certified only by a gap beyond both sags.
  EXPECT_FALSE(pd::certify_by_bound(result(Status::kSeparated, 0.0), {0, 0}, c));
  EXPECT_FALSE(pd::certify_by_bound(result(Status::kSeparated, 0.0), {0, 0}, c, 0.019));
  e = pd::certify_by_bound(result(Status::kSeparated, 0.0), {0, 0}, c, 0.021);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->verdict, ExactVerdict::kSeparated);
}

// A pair the meshes found touching (no overlap above the coordinates'
// resolution) or apart with no gap beyond the sags: the solids overlap by at
// most the meshes' upper end plus twice the sag, certified within the
// tolerance; the status stays the meshes'.
TEST(BrepConfirm, AContactWithinTheToleranceIsCertifiedAndKeepsItsStatus) {
  const ExactContext c = context(0.05, 0.0125);
  PairResult seated = result(Status::kSeparated, 0.0, std::array{0.0, 0.008});
  auto e = pd::certify_within_tolerance(seated, c);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->verdict, ExactVerdict::kFalsePositive);
  EXPECT_EQ(e->basis, ExactBasis::kBound);
  EXPECT_DOUBLE_EQ((*e->depth_bounds)[0], 0.0);
  EXPECT_DOUBLE_EQ((*e->depth_bounds)[1], 0.033);
  // Meshes apart (no bracket): the solids' overlap is at most 2s.
  e = pd::certify_within_tolerance(result(Status::kSeparated, 0.0), c);
  ASSERT_TRUE(e);
  EXPECT_DOUBLE_EQ((*e->depth_bounds)[1], 0.025);
  // Not when the widened end passes the tolerance, the sags are estimates, a
  // clearance is checked (contact breaks it), or the meshes overlap.
  EXPECT_FALSE(pd::certify_within_tolerance(seated, context(0.05, 0.025)));
  EXPECT_FALSE(pd::certify_within_tolerance(seated, context(0.05, 0.0125, false)));
  ExactContext clearance = c;
  clearance.clearance = 0.1;
  EXPECT_FALSE(pd::certify_within_tolerance(seated, clearance));
  EXPECT_FALSE(pd::certify_within_tolerance(
      result(Status::kFalsePositive, 0.008, std::array{0.004, 0.008}), c));
  // Apart by no more than the sags is no certificate of being apart.
  EXPECT_FALSE(pd::certify_by_bound(seated, {0, 0}, c, 0.02));
}

ExactMeasure measure(double distance, double lower, std::optional<double> upper,
                     std::optional<double> volume = {}) {
  ExactMeasure m;
  m.ok = true;
  m.distance = distance;
  m.lower = lower;
  m.upper = upper;
  m.volume = volume;
  m.seconds = 0.5;
  return m;
}

TEST(BrepConfirm, TheSolidsDecideWhereTheyAgreeWithTheWidenedBracket) {
  // Mesh said interference (bracket [0.03, 0.3], estimated sags); the solids
  // touch: the pair is separated, its depth 0, and says so.
  PairResult r = result(Status::kInterference, 0.03, std::array{0.03, 0.3});
  const ExactContext estimated = context(0.01, 0.01, false);
  pd::decide_exact(r, {0.03, 0.3}, estimated, measure(0.0, 0.0, 0.0, 0.0));
  ASSERT_TRUE(r.exact);
  EXPECT_EQ(r.exact->verdict, ExactVerdict::kTouching);
  EXPECT_EQ(r.exact->basis, ExactBasis::kSolids);
  EXPECT_EQ(r.status, Status::kSeparated);
  EXPECT_EQ(r.depth, 0.0);
  EXPECT_EQ(r.depth_source, "exact");
  EXPECT_EQ(pd::exact_sentence(*r.exact), "confirmed on the exact solids");

  // The solids thick beyond the tolerance: interference, depth the lower end.
  r = result(Status::kFalsePositive, 0.005, std::array{0.0, 0.005});
  pd::decide_exact(r, {0.0, 0.005}, context(0.01, 0.004, false), measure(0.0, 0.02, 0.03, 1.5));
  EXPECT_EQ(r.exact->verdict, ExactVerdict::kInterference);
  EXPECT_EQ(r.status, Status::kInterference);
  EXPECT_DOUBLE_EQ(r.depth, 0.02);
  EXPECT_DOUBLE_EQ(*r.exact->volume, 1.5);

  // The meshes prove an overlap the solids deny beyond the sags: inconsistent,
  // the mesh verdict stands.
  r = result(Status::kInterference, 1.0, std::array{1.0, 1.2});
  pd::decide_exact(r, {1.0, 1.2}, context(0.05, 0.01), measure(2.5, 0.0, std::nullopt));
  EXPECT_EQ(r.exact->verdict, ExactVerdict::kInconsistent);
  EXPECT_EQ(r.status, Status::kInterference);
  EXPECT_EQ(r.depth, 1.0);
  EXPECT_NE(r.exact->reason.find("2.5 apart"), std::string::npos) << r.exact->reason;

  // A Boolean that ran out of time with the bracket around the tolerance.
  r = result(Status::kUndecided, 0.0, std::array{0.0, 0.2});
  ExactMeasure late = measure(0.0, 0.001, std::nullopt);
  late.common_timed_out = true;
  pd::decide_exact(r, {0.0, 0.2}, context(0.05, 0.01, false), late);
  EXPECT_EQ(r.exact->verdict, ExactVerdict::kTimeout);
  EXPECT_EQ(r.status, Status::kUndecided);

  // The time box ended the distance with the nearest faces' boxes meeting:
  // not a contact, a timeout; the mesh verdict stands. With the boxes still
  // apart beyond the contact band, separated by at least that much.
  r = result(Status::kSeparated, 0.0);
  ExactMeasure unsettled = measure(0.0, 0.0, std::nullopt);
  unsettled.distance_exact = false;
  unsettled.distance_timed_out = true;
  pd::decide_exact(r, {0, 0}, context(0.05, 0.01, false), unsettled);
  EXPECT_EQ(r.exact->verdict, ExactVerdict::kTimeout);
  EXPECT_EQ(r.status, Status::kSeparated);
  EXPECT_NE(r.exact->reason.find("not settled"), std::string::npos) << r.exact->reason;
  r = result(Status::kSeparated, 0.0);
  unsettled.distance = 0.3;
  pd::decide_exact(r, {0, 0}, context(0.05, 0.01, false), unsettled);
  EXPECT_EQ(r.exact->verdict, ExactVerdict::kSeparated);
  EXPECT_NE(r.exact->reason.find("at least 0.3"), std::string::npos) << r.exact->reason;

  // Apart on the solids, as the meshes allow: separated with its distance.
  r = result(Status::kSeparated, 0.0);
  pd::decide_exact(r, {0, 0}, context(0.05, 0.01), measure(0.1, 0.0, std::nullopt));
  EXPECT_EQ(r.exact->verdict, ExactVerdict::kSeparated);
  EXPECT_DOUBLE_EQ(*r.distance, 0.1);

  // A depth the hulls measured is a move, which the solids' thickness bounds
  // from below only: thinner than the move (a ball buried in a block), not
  // inconsistent, and within the tolerance not a false positive; thicker than
  // the tolerance, an interference.
  r = result(Status::kInterference, 12.97);
  pd::decide_exact(r, {12.97, 12.97}, context(12.95, 0.04), measure(0.0, 6.0, 6.0));
  EXPECT_EQ(r.exact->verdict, ExactVerdict::kFailed);
  EXPECT_FALSE(r.exact->depth_bounds);
  EXPECT_EQ(r.status, Status::kInterference);
  EXPECT_DOUBLE_EQ(r.depth, 12.97);
  r = result(Status::kInterference, 12.97);
  pd::decide_exact(r, {12.97, 12.97}, context(5.0, 0.04), measure(0.0, 6.0, 6.0));
  EXPECT_EQ(r.exact->verdict, ExactVerdict::kInterference);
  EXPECT_EQ(r.status, Status::kInterference);

  // A failure keeps the mesh verdict with its reason.
  r = result(Status::kFalsePositive, 0.01);
  ExactMeasure failed;
  failed.error = "Open CASCADE failed: BRep_API: command not done";
  pd::decide_exact(r, {0.0, 0.01}, context(0.05, 0.01), failed);
  EXPECT_EQ(r.exact->verdict, ExactVerdict::kFailed);
  EXPECT_EQ(r.status, Status::kFalsePositive);
  EXPECT_NE(pd::exact_sentence(*r.exact).find("BRep_API"), std::string::npos);
}

}  // namespace

namespace {

// The time box holds in the distance too: with no time at all the nearest
// faces' boxes (meeting here) are all the distance says, and the pair is a
// timeout, not a contact; with time, the boxes touch and the distance is 0.
TEST(BrepConfirm, TheTimeBoxEndsTheDistanceWithoutCallingItContact) {
  const std::string dir = pd_test::process_dir();
  pd_test::write_brep_part(dir + "left.brep",
                           {"left", {pd_test::BrepSolid::Kind::kBox, {10, 10, 10}}});
  pd_test::write_brep_part(
      dir + "right.brep",
      {"right", {pd_test::BrepSolid::Kind::kBox, {10, 10, 10}}, Vec3(10, 0, 0)});
  pd::ExactRequest q;
  q.common = false;
  q.seconds = 0.0;
  const ExactMeasure late = pd::measure_exact_pair({dir + "left.brep"}, {dir + "right.brep"}, q);
  ASSERT_TRUE(late.ok) << late.error;
  EXPECT_TRUE(late.distance_timed_out);
  EXPECT_FALSE(late.distance_exact);
  PairResult r = result(Status::kSeparated, 0.0);
  pd::decide_exact(r, {0, 0}, context(0.05, 0.01, false), late);
  EXPECT_EQ(r.exact->verdict, ExactVerdict::kTimeout);

  q.seconds = 10.0;
  const ExactMeasure settled = pd::measure_exact_pair({dir + "left.brep"}, {dir + "right.brep"}, q);
  ASSERT_TRUE(settled.ok) << settled.error;
  EXPECT_FALSE(settled.distance_timed_out);
  EXPECT_NEAR(*settled.distance, 0.0, 1e-9);
}

}  // namespace
