// One pair of parts solved (batch/pair_solve.h) on boxes whose answers are
// known: a unit cube and a smaller box overlapping it by 0.1 along x (depth
// 0.1, +x), the same box 0.5 apart (a clearance measures the gap), a part that
// could not be loaded, the pair's rounding scale and the tolerance under auto.
#include <gtest/gtest.h>

#include <cmath>

#include "batch/pair_solve.h"
#include "box_points.h"
#include "inline_part.h"

using namespace pd;
using pd_test::box_points;
using pd_test::inline_part;

namespace {

const Part kCube = inline_part("a", box_points(Vec3::Zero(), Vec3::Ones()));

// A 1 × 0.6 × 0.4 box from x = `x`, within the cube's y and z.
Part box_at(double x) {
  return inline_part("b", box_points(Vec3(x, 0.2, 0.3), Vec3(x + 1, 0.8, 0.7)));
}

PairResult solve(const Part& b, double tolerance, const PairChecks& checks = {},
                 Method method = Method::kMlsl) {
  static IpoptLocalSolver ipopt;
  SolverSettings s;
  s.method = method;
  return solve_part_pair(3, kCube, 7, b, s, tolerance, ipopt, checks);
}

PairChecks clearance(double min) {
  PairChecks c;
  c.clearance = min;
  return c;
}

}  // namespace

TEST(PairSolve, OverlappingBoxesAreDecidedAgainstTheTolerance) {
  for (Method m : {Method::kMlsl, Method::kExact}) {
    const PairResult r = solve(box_at(0.9), 0.05, {}, m);
    SCOPED_TRACE(r.method);
    EXPECT_EQ(r.method, method_name(m));
    EXPECT_EQ(r.a, 3);
    EXPECT_EQ(r.b, 7);
    EXPECT_EQ(r.status, Status::kInterference);
    EXPECT_NEAR(r.depth, 0.1, 1e-12);
    EXPECT_NEAR((r.direction - Vec3::UnitX()).norm(), 0.0, 1e-9);  // moving b along +x
    EXPECT_EQ(r.margin, 0.05 - r.depth);
    EXPECT_FALSE(r.distance);
    EXPECT_TRUE(r.error.empty());
    EXPECT_FALSE(r.pieces);  // one piece each
    // Where: in the overlap [0.9, 1] × [0.2, 0.8] × [0.3, 0.7].
    ASSERT_TRUE(r.at);
    const Vec3 lo(0.9 - 1e-9, 0.2 - 1e-9, 0.3 - 1e-9), hi(1 + 1e-9, 0.8 + 1e-9, 0.7 + 1e-9);
    EXPECT_TRUE((r.at->array() >= lo.array()).all() && (r.at->array() <= hi.array()).all())
        << r.at->transpose();
  }
  const PairResult fp = solve(box_at(0.9), 0.2);
  EXPECT_EQ(fp.status, Status::kFalsePositive);
  EXPECT_NEAR(fp.margin, 0.1, 1e-12);
  EXPECT_TRUE(fp.at);
}

TEST(PairSolve, ApartBoxesAreSeparatedAndAClearanceMeasuresTheirGap) {
  const PairResult r = solve(box_at(1.5), 0.05);
  EXPECT_EQ(r.status, Status::kSeparated);
  EXPECT_EQ(r.depth, 0.0);
  EXPECT_FALSE(r.at);  // a clean pair needs no place
  EXPECT_FALSE(r.clearance_min);
  // Required 1, found 0.5: a violation, placed in the gap.
  const PairResult v = solve(box_at(1.5), 0.05, clearance(1.0));
  EXPECT_EQ(v.status, Status::kClearanceViolation);
  ASSERT_TRUE(v.distance);
  EXPECT_NEAR(*v.distance, 0.5, 1e-9);
  EXPECT_EQ(v.clearance_min, 1.0);
  ASSERT_TRUE(v.at);
  EXPECT_GE(v.at->x(), 1 - 1e-9);
  EXPECT_LE(v.at->x(), 1.5 + 1e-9);
  // Required 0.4: met.
  const PairResult ok = solve(box_at(1.5), 0.05, clearance(0.4));
  EXPECT_EQ(ok.status, Status::kSeparated);
  ASSERT_TRUE(ok.distance);
  EXPECT_NEAR(*ok.distance, 0.5, 1e-9);
  // Touching face to face: contact, not a violation.
  EXPECT_EQ(solve(box_at(1.0), 0.05, clearance(1.0)).status, Status::kSeparated);
}

TEST(PairSolve, APartThatCouldNotBeLoadedMakesItsPairAnError) {
  Part broken = box_at(0.9);
  broken.id = "bracket";
  broken.error = "no such file";
  const PairResult r = solve(broken, 0.05);
  EXPECT_EQ(r.status, Status::kError);
  EXPECT_EQ(r.error, "part \"bracket\" could not be loaded: no such file");
  EXPECT_EQ(r.a, 3);
  EXPECT_EQ(r.b, 7);
}

TEST(PairSolve, PairSizeIsTheLargestCoordinatePlusTheDiagonal) {
  // The joint box of the cube and box_at(0.9) is [0, 1.9] × [0, 1] × [0, 1].
  EXPECT_DOUBLE_EQ(pair_size(kCube, box_at(0.9)), 1.9 + std::sqrt(1.9 * 1.9 + 2));
  // Far from the origin the coordinates count: they were rounded at 1e6.
  const Part far_a = inline_part("a", box_points(Vec3(1e6, 0, 0), Vec3(1e6 + 1, 1, 1)));
  const Part far_b = inline_part("b", box_points(Vec3(1e6 + 2, 0, 0), Vec3(1e6 + 3, 1, 1)));
  EXPECT_DOUBLE_EQ(pair_size(far_a, far_b), 1e6 + 3 + std::sqrt(9 + 2));
  // A box beyond ~1e154 has no finite diagonal squared, but a finite size.
  Part huge_a = far_a, huge_b = far_b;
  huge_a.box = {Vec3(-1e200, 0, 0), Vec3(0, 1, 1)};
  huge_b.box = {Vec3(0, 0, 0), Vec3(1e200, 1, 1)};
  EXPECT_NEAR(pair_size(huge_a, huge_b), 3e200, 1e186);
  huge_b.box.hi.x() = 1.7e308;
  EXPECT_TRUE(std::isinf(pair_size(huge_a, huge_b)));
}

TEST(PairSolve, AToleranceBelowThePairsResolutionIsSaid) {
  // 1 mm boxes 0.5 apart at 1e6 mm: depths below 1e-11 · 1e6 = 1e-5 mm are contact.
  const Part a = inline_part("a", box_points(Vec3(1e6, 0, 0), Vec3(1e6 + 1, 1, 1)));
  const Part b = inline_part("b", box_points(Vec3(1e6 + 1.5, 0, 0), Vec3(1e6 + 2.5, 1, 1)));
  IpoptLocalSolver ipopt;
  const PairResult r = solve_part_pair(0, a, 1, b, SolverSettings{}, 1e-6, ipopt);
  EXPECT_EQ(r.status, Status::kSeparated);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].rfind("depth below the resolvable scale", 0), 0u) << r.warnings[0];
  EXPECT_TRUE(solve_part_pair(0, a, 1, b, SolverSettings{}, 1e-4, ipopt).warnings.empty());
}

TEST(PairSolve, UnderAutoThePairsOwnBandDecides) {
  PairChecks checks;
  EXPECT_EQ(pair_tolerance_of(checks, 0.05), 0.05);
  checks.tolerance = PairTolerance{0.2, "measured", "a: flat; b: flat", {}, {}, 0.0};
  EXPECT_EQ(pair_tolerance_of(checks, 0.05), 0.2);
  // Depth 0.1: above the scene's 0.05, within the pair's 0.2.
  const PairResult r = solve(box_at(0.9), 0.05, checks);
  EXPECT_EQ(r.status, Status::kFalsePositive);
  EXPECT_NEAR(r.margin, 0.1, 1e-12);
  // The band is recorded; a refined result (its depth the parts' own, at
  // their contact) is decided again against the band there.
  PairResult noted = r;
  note_pair_tolerance(noted, {});
  EXPECT_FALSE(noted.tolerance);
  int asked = 0;
  checks.tolerance->at_contact = [&](const Vec3& at, double) {
    ++asked;
    EXPECT_EQ(at, *r.at);
    return PairTolerance{0.05, "measured", "narrower", {}, {}, 0.0};
  };
  note_pair_tolerance(noted, checks);
  EXPECT_EQ(noted.tolerance, 0.2);
  EXPECT_EQ(noted.tolerance_source, "measured");
  EXPECT_EQ(noted.tolerance_basis, "a: flat; b: flat");
  EXPECT_EQ(noted.status, Status::kFalsePositive);
  EXPECT_EQ(asked, 0);  // the hull's depth: not at the parts' contact
  noted.depth_source = "thickness";
  note_pair_tolerance(noted, checks);
  EXPECT_EQ(asked, 1);
  EXPECT_EQ(noted.status, Status::kInterference);  // 0.1 > 0.05
  EXPECT_EQ(noted.tolerance, 0.05);
  EXPECT_EQ(noted.tolerance_basis, "narrower");
}

// A pair the refinement decides on the parts (a nonconvex part) needs no
// sampling once the hulls' certified overlap is above the tolerance: the
// bracket's upper end is its hull depth, an upper bound, with no Ipopt solve.
// Below the tolerance, or for convex parts, the hull stage runs as before.
TEST(PairSolve, APairTheRefinementDecidesStopsAtTheBracketAboveTheTolerance) {
  // A ball of 400 vertices (sampling would be needed) deep in the cube.
  Points ball(3, 400);
  for (int k = 0; k < 400; ++k) {
    const double z = 1.0 - (2.0 * k + 1.0) / 400.0, r = std::sqrt(1.0 - z * z);
    const double t = 2.399963229728653 * k;  // golden angle
    ball.col(k) = Vec3(0.7 + 0.25 * r * std::cos(t), 0.5 + 0.25 * r * std::sin(t), 0.5 + 0.25 * z);
  }
  Part nonconvex = inline_part("b", ball);
  nonconvex.mode = Pieces::kAuto;
  nonconvex.convex = false;
  nonconvex.surface.emplace();  // refinable: decided on its surface after the hull stage
  ASSERT_TRUE(nonconvex.refinable());
  const PairResult early = solve(nonconvex, 0.05);
  EXPECT_EQ(early.status, Status::kInterference);
  EXPECT_EQ(early.stats.stop_reason, StopReason::kAboveTolerance);
  EXPECT_EQ(early.stats.ipopt_calls, 0);
  const PairResult full = solve(inline_part("b", ball), 0.05);
  EXPECT_NE(full.stats.stop_reason, StopReason::kAboveTolerance);
  EXPECT_GE(early.depth, full.depth - 1e-12);  // an upper bound of the hull depth
  EXPECT_LE(early.depth, full.depth + 0.01);
  // Against a tolerance the bracket does not clear, the hull stage decides as before.
  const PairResult shallow = solve(nonconvex, 10.0);
  EXPECT_EQ(shallow.status, Status::kFalsePositive);
  EXPECT_NE(shallow.stats.stop_reason, StopReason::kAboveTolerance);
}
