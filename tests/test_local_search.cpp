// One local search (solve/local_search.h) on unit cubes: Q = P + (0.1, 0.2,
// 0.3) makes P − Q the box [−1.1, 0.9] × [−1.2, 0.8] × [−1.3, 0.7], whose gap
// has a local minimum at each facet normal (0.7 at +z, 0.9 at +x, …). Started
// near an optimum, each search ends on it; the polish lands on the facet
// exactly; the counts add up. Apart cubes give their signed gap.
#include <gtest/gtest.h>

#include <tuple>

#include "box_points.h"
#include "solve/local_search.h"

using namespace pd;
using pd_test::box_points;

namespace {

PairProblem cube_and_cube_at(const Vec3& shift) {
  return PairProblem(box_points(Vec3::Zero(), Vec3::Ones()),
                     box_points(shift, shift + Vec3::Ones()));
}

const Vec3 kDiagonal(0.1, 0.2, 0.3);

}  // namespace

TEST(LocalSearch, DescendThenPolishLandsOnTheNearestFacet) {
  const PairProblem pr = cube_and_cube_at(kDiagonal);
  const double scale = pr.frame().scale;
  IpoptLocalSolver ipopt;
  const std::tuple<Vec3, Vec3, double> starts[] = {{Vec3(0.1, -0.15, 1), Vec3::UnitZ(), 0.7},
                                                   {Vec3(1, 0.15, 0.1), Vec3::UnitX(), 0.9},
                                                   {Vec3(0.1, -1, -0.15), -Vec3::UnitY(), 1.2}};
  for (const auto& [start, axis, depth] : starts) {
    SCOPED_TRACE(start.transpose());
    SolveStats stats;
    const DescentOutcome d = descend(pr, start, stats);
    EXPECT_EQ(stats.local_solves, 1);
    EXPECT_EQ(stats.alpha_evaluations, d.evaluations);
    EXPECT_EQ(d.v, smooth_descent(pr.p(), pr.q(), start).v);
    const LocalResult r = polish(pr, ipopt, d.v, stats);
    ASSERT_TRUE(r.converged) << r.status;
    EXPECT_TRUE(r.status.empty());
    EXPECT_NEAR((r.v - axis).norm(), 0.0, 1e-15) << r.v.transpose();  // snapped
    EXPECT_EQ(r.gap, pr.gap(r.v));
    EXPECT_NEAR(r.gap * scale, depth, 1e-15);
    EXPECT_GE(stats.ipopt_calls, 1);
    EXPECT_EQ(stats.ipopt_failures, 0);
    EXPECT_EQ(stats.local_solves, 1);  // the polish is no new search
  }
}

TEST(LocalSearch, ThePapersSearchEndsAtTheOptimumToIpoptsTolerance) {
  const PairProblem pr = cube_and_cube_at(kDiagonal);
  IpoptLocalSolver ipopt;
  SolveStats stats;
  const LocalResult r = paper_local_search(pr, ipopt, Vec3(0.2, -0.1, 1).normalized(), stats);
  ASSERT_TRUE(r.converged) << r.status;
  EXPECT_LT(angle_between(r.v, Vec3::UnitZ()), 1e-6) << r.v.transpose();
  EXPECT_EQ(r.gap, pr.gap(r.v));  // a true upper bound of the minimum
  EXPECT_GE(r.gap, pr.gap(Vec3::UnitZ()));
  EXPECT_NEAR(r.gap * pr.frame().scale, 0.7, 1e-6);
  EXPECT_EQ(stats.local_solves, 1);
  EXPECT_EQ(stats.ipopt_calls, 1);
  EXPECT_GT(stats.ipopt_iterations, 0);
}

TEST(LocalSearch, ASignedPolishGivesTheSeparationOfApartCubes) {
  // Apart by 0.5 along x: with α free, the gap's minimum is −0.5 at +x.
  const PairProblem pr = cube_and_cube_at(Vec3(1.5, 0, 0));
  IpoptLocalSolver ipopt;
  SolveStats stats;
  const LocalResult r = polish(pr, ipopt, Vec3(1, 0.05, 0.02).normalized(), stats, true);
  ASSERT_TRUE(r.converged) << r.status;
  EXPECT_NEAR((r.v - Vec3::UnitX()).norm(), 0.0, 1e-12) << r.v.transpose();
  EXPECT_NEAR(r.gap * pr.frame().scale, -0.5, 1e-12);
}
