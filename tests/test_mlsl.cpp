// pdcheck's MLSL (solve/mlsl.h) against the exact method: equal on the
// paper's pairs, large coordinates and Zhou's spheres; the same seed the same
// bits.
#include <gtest/gtest.h>

#include "method_solve.h"
#include "solve/mlsl.h"

using namespace pd;
using pd_test::gap_world;
using pd_test::solve;

namespace {

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
