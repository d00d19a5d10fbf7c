// The depth methods (methods.cpp, solve_convex_pair) against the exact
// reference (the hull of the Minkowski difference): every method an upper
// bound, mlsl equal to it on the paper's pairs, the same seed the same bits.
#include <gtest/gtest.h>

#include "corpus/generators.h"
#include "solve/exact.h"
#include "solve/methods.h"
#include "solve/objective.h"

using namespace pd;

namespace {

double gap_world(const Points& a, const Points& b, const Vec3& v) {
  return (v.transpose() * a).maxCoeff() - (v.transpose() * b).minCoeff();
}

DepthSolution solve(const testgen::PairCase& c, Method m, std::uint64_t seed = 1) {
  static IpoptLocalSolver ipopt;
  SolverSettings s;
  s.method = m;
  s.seed = seed;
  return solve_convex_pair(c.a, c.b, s, ipopt);
}

Points cube(double h, const Vec3& c) {
  Points p(3, 8);
  for (int k = 0; k < 8; ++k)
    p.col(k) = c + h * Vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
  return p;
}

void expect_matches_exact(const testgen::PairCase& c, const std::string& what) {
  const DepthSolution e = solve(c, Method::kExact);
  const DepthSolution m = solve(c, Method::kMlsl);
  ASSERT_GT(e.depth, 0) << what;
  EXPECT_LE(std::abs(m.depth - e.depth), 1e-9 * e.depth) << what << " exact " << e.depth;
  EXPECT_NEAR(m.direction.norm(), 1.0, 1e-12);
  // The reported direction really achieves the depth.
  EXPECT_LE(std::abs(gap_world(c.a, c.b, m.direction) - m.depth), 1e-9 * e.depth) << what;
  EXPECT_TRUE(m.fallback.empty()) << m.fallback;
}

}  // namespace

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

TEST(Mlsl, PaperLikePairsMatchExact) {
  SphereSampler r(2024);
  for (int k = 0; k < 25; ++k)
    expect_matches_exact(testgen::paper_like(r), "paper-like " + std::to_string(k));
}

TEST(Mlsl, LargeCoordinatePairsMatchExact) {
  SphereSampler r(14);
  for (int k = 0; k < 3; ++k)
    expect_matches_exact(testgen::large_coordinates(r), "problem-14-like " + std::to_string(k));
}

TEST(Mlsl, ZhouSpheresMatchExact) {
  SphereSampler r(2006);
  for (int m : {10, 50, 200})
    expect_matches_exact(testgen::zhou_spheres(r, m), "spheres m=" + std::to_string(m));
}

TEST(Mlsl, SameSeedSameBits) {
  SphereSampler r(5);
  const auto c = testgen::paper_like(r);
  const DepthSolution a = solve(c, Method::kMlsl, 9), b = solve(c, Method::kMlsl, 9);
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_EQ(a.direction, b.direction);
}

TEST(Methods, EveryMethodIsAnUpperBoundOnExact) {
  // Every method reports the gap at a real direction, so it can never be below
  // the true depth; the Ipopt methods land on the exact one on an easy case.
  SphereSampler r(3);
  for (int k = 0; k < 3; ++k) {
    const auto c = testgen::paper_like(r);
    const double exact = solve(c, Method::kExact).depth;
    for (Method m : {Method::kMlslPaper, Method::kGsLocal, Method::kGrid}) {
      const DepthSolution s = solve(c, m);
      EXPECT_GE(s.depth, exact * (1 - 1e-9)) << method_name(m);
      EXPECT_LE(s.depth, exact * 1.5) << method_name(m);
      EXPECT_TRUE(std::isfinite(s.depth));
    }
  }
}
