// The paper's 5-variable local problem through Ipopt (solve/ipopt_local.h), in
// world coordinates, on unit cubes overlapping by 0.1 along x: its optimum is
// v = +x, c = max p·v = 1, α = 0.1; the paper's start from a direction; the
// reduced problem over the active faces; α free on apart cubes; a NaN input
// is a failure with Ipopt's status.
#include <gtest/gtest.h>

#include <cmath>

#include "box_points.h"
#include "solve/ipopt_local.h"

using namespace pd;
using pd_test::box_points;

namespace {

const Points kA = box_points(Vec3::Zero(), Vec3::Ones());

Points cube_at(double x) {
  return box_points(Vec3(x, 0, 0), Vec3(x + 1, 1, 1));
}

// The vertices of box_points with x at its low (hi = false) or high end.
std::vector<int> x_face(bool hi) {
  std::vector<int> ids;
  for (int k = 0; k < 8; ++k)
    if (bool(k & 1) == hi) ids.push_back(k);
  return ids;
}

void expect_optimum(const LocalOutcome& o, double c, double alpha, double tol) {
  ASSERT_TRUE(o.converged) << o.status;
  EXPECT_EQ(o.status, "solve_succeeded");
  EXPECT_NEAR(o.v.norm(), 1.0, 1e-15);
  EXPECT_NEAR((o.v - Vec3::UnitX()).norm(), 0.0, tol) << o.v.transpose();
  EXPECT_NEAR(o.c, c, tol);
  EXPECT_NEAR(o.alpha, alpha, tol);
}

}  // namespace

TEST(IpoptLocal, AllIndicesCountsUp) {
  EXPECT_EQ(all_indices(4), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_TRUE(all_indices(0).empty());
}

TEST(IpoptLocal, ThePapersStartIsTheSupportLevelAndGap) {
  const Points b = cube_at(0.9);
  const LocalStart s = IpoptLocalSolver::paper_start(kA, b, Vec3::UnitX());
  EXPECT_EQ(s.v, Vec3::UnitX());
  EXPECT_EQ(s.c, 1.0);
  EXPECT_EQ(s.alpha, 1.0 - 0.9);
  const LocalStart y = IpoptLocalSolver::paper_start(kA, b, -Vec3::UnitY());
  EXPECT_EQ(y.c, 0.0);
  EXPECT_EQ(y.alpha, 1.0);
}

TEST(IpoptLocal, TheFullAndTheReducedProblemReachTheOptimum) {
  const Points b = cube_at(0.9);
  IpoptLocalSolver ipopt;
  const Vec3 v0 = Vec3(1, 0.1, 0.05).normalized();
  const LocalOutcome full = ipopt.solve(kA, b, all_indices(8), all_indices(8),
                                        IpoptLocalSolver::paper_start(kA, b, v0), false);
  expect_optimum(full, 1.0, 0.1, 1e-7);
  EXPECT_GT(full.iterations, 0);
  // Only the faces active at +x (x = 1 of a, x = 0.9 of b), warm from the optimum.
  const LocalOutcome reduced =
      ipopt.solve(kA, b, x_face(true), x_face(false),
                  IpoptLocalSolver::paper_start(kA, b, Vec3::UnitX()), true);
  expect_optimum(reduced, 1.0, 0.1, 1e-7);
  // One application serves every solve: the same problem, the same answer.
  const LocalOutcome again = ipopt.solve(kA, b, all_indices(8), all_indices(8),
                                         IpoptLocalSolver::paper_start(kA, b, v0), false);
  EXPECT_EQ(again.v, full.v);
  EXPECT_EQ(again.alpha, full.alpha);
  EXPECT_EQ(again.iterations, full.iterations);
}

TEST(IpoptLocal, AlphaFreeIsTheSignedGapOfApartCubes) {
  // Apart by 0.5: α >= 0 stops at 0 (any separating v); α free reaches −0.5 at +x.
  const Points b = cube_at(1.5);
  IpoptLocalSolver ipopt;
  const LocalStart start = IpoptLocalSolver::paper_start(kA, b, Vec3(1, 0.1, 0.05).normalized());
  expect_optimum(ipopt.solve(kA, b, all_indices(8), all_indices(8), start, false, true), 1.0, -0.5,
                 1e-7);
  const LocalOutcome bounded = ipopt.solve(kA, b, all_indices(8), all_indices(8), start, false);
  ASSERT_TRUE(bounded.converged) << bounded.status;
  EXPECT_NEAR(bounded.alpha, 0.0, 1e-7);
}

TEST(IpoptLocal, ANonFiniteInputIsAFailureWithItsStatus) {
  Points b = cube_at(0.9);
  b(0, 3) = std::nan("");
  IpoptLocalSolver ipopt;
  const LocalOutcome o =
      ipopt.solve(kA, b, all_indices(8), all_indices(8), {Vec3::UnitX(), 1.0, 0.1}, false);
  EXPECT_FALSE(o.converged);
  EXPECT_FALSE(o.status.empty());
  EXPECT_NE(o.status, "solve_succeeded");
}
