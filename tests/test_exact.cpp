// The exact method (solve/exact.h, the hull of the Minkowski difference): the
// minimum of the gap over the sphere, the distance of apart pairs, libccd's
// failing case.
#include <gtest/gtest.h>

#include "method_solve.h"
#include "solve/exact.h"

using namespace pd;
using pd_test::cube;
using pd_test::gap_world;
using pd_test::solve;

TEST(Exact, BoundedByDenseDirectionSampling) {
  // The exact depth is the minimum of the gap over the sphere: no sampled
  // direction may beat it, and the best of 40,000 directions comes close.
  SphereSampler r(11);
  for (int k = 0; k < 200; ++k) {
    const auto c = testgen::paper_like(r);
    const DepthSolution e = solve(c, Method::kExact);
    ASSERT_GT(e.depth, 0.0) << k;
    EXPECT_NEAR(gap_world(c.a, c.b, e.direction), e.depth, 1e-9 * e.depth) << k;
    SphereSampler dirs(1000 + k);
    double best = 1e300;
    for (int s = 0; s < 40000; ++s) {
      const double g = gap_world(c.a, c.b, dirs.direction());
      EXPECT_GE(g, e.depth * (1 - 1e-12)) << k;
      best = std::min(best, g);
    }
    const double size = (c.a.rowwise().maxCoeff() - c.a.rowwise().minCoeff()).norm();
    EXPECT_LE(best - e.depth, 0.05 * size) << k;
  }
}

TEST(Exact, SeparatedPairsGiveDistance) {
  const testgen::PairCase c{cube(1, Vec3::Zero()), cube(1, Vec3(5, 0, 0))};
  const DepthSolution e = solve(c, Method::kExact);
  EXPECT_EQ(e.depth, 0.0);
  ASSERT_TRUE(e.distance);
  EXPECT_NEAR(*e.distance, 3.0, 1e-12);
  EXPECT_NEAR(e.direction.x(), 1.0, 1e-12);  // from a to b
}

TEST(Exact, LibccdCubesShiftedAlongZ) {
  // libccd's tracker: 2x2x2 cubes, one shifted 1.9 along z; libccd said depth 0, NaN direction.
  const testgen::PairCase c{cube(1, Vec3::Zero()), cube(1, Vec3(0, 0, 1.9))};
  for (Method m : {Method::kExact, Method::kMlsl}) {
    const DepthSolution s = solve(c, m);
    EXPECT_NEAR(s.depth, 0.1, 1e-12) << method_name(m);
    EXPECT_TRUE(s.direction.allFinite());
    EXPECT_NEAR(s.direction.z(), 1.0, 1e-9) << method_name(m);  // the pole
  }
}
