// The paper's grid methods (solve/grid.h): GS-k evaluates its 2k(k+1)
// directions and keeps the lowest gap, an upper bound on the exact depth that
// is exact when the optimum lies on the grid; GS-SQP's local searches land on
// the exact depth of an easy pair.
#include <gtest/gtest.h>

#include "method_solve.h"
#include "solve/exact.h"
#include "solve/grid.h"

using namespace pd;

TEST(Grid, CountsItsDirectionsAndIsExactOnTheGrid) {
  // Cubes stacked along z, 0.1 in: the optimum is the pole, a grid direction.
  const Points a = pd_test::cube(1, Vec3::Zero()), b = pd_test::cube(1, Vec3(0, 0, 1.9));
  for (int k : {4, 12}) {
    const PairProblem pr(a, b);
    const DepthSolution g = grid_depth(pr, k);
    EXPECT_EQ(g.stats.alpha_evaluations, 2L * k * (k + 1)) << k;
    EXPECT_NEAR(pr.frame().length_to_world(g.depth), 0.1, 1e-12) << k;
    EXPECT_NEAR(std::abs(g.direction.z()), 1.0, 1e-12) << k;
  }
}

TEST(Grid, AnUpperBoundOnExactThatTightensWithK) {
  SphereSampler r(8);
  for (int t = 0; t < 5; ++t) {
    const testgen::PairCase c = testgen::paper_like(r);
    const PairProblem pr(c.a, c.b);
    const double exact = exact_depth(pr.p(), pr.q()).depth;
    ASSERT_GT(exact, 0.0);
    const double coarse = grid_depth(pr, 6).depth, fine = grid_depth(pr, 48).depth;
    EXPECT_GE(coarse, exact * (1 - 1e-12)) << t;
    EXPECT_GE(fine, exact * (1 - 1e-12)) << t;
    // k = 6·8: every grid of 6 is a sub-grid of 48, so the finer one is never worse.
    EXPECT_LE(fine, coarse + 1e-15) << t;
    EXPECT_NEAR(pr.gap(grid_depth(pr, 48).direction), fine, 1e-15 * (1 + fine)) << t;
  }
}

TEST(Grid, GsLocalReachesTheExactDepthOfAnEasyPair) {
  const Points a = pd_test::cube(1, Vec3::Zero()), b = pd_test::cube(1, Vec3(1.7, 0.3, 0.2));
  const PairProblem pr(a, b);
  IpoptLocalSolver ipopt;
  const DepthSolution g = gs_local_depth(pr, ipopt, 3);
  const double exact = exact_depth(pr.p(), pr.q()).depth;
  EXPECT_NEAR(g.depth, exact, 1e-9 * exact);
  EXPECT_NEAR(pr.frame().length_to_world(g.depth), 0.3, 1e-9);
}
