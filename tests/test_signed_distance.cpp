// The signed distance (solve/signed_distance.h), depth or minus the distance,
// against the exact method's, cold and warm-started. The suite keeps its name
// (Checks: scripts/sanitize.sh lists it among the slow tests).
#include <gtest/gtest.h>

#include "corpus/generators.h"
#include "solve/methods.h"
#include "solve/signed_distance.h"

using namespace pd;

TEST(Checks, IpoptDistanceMatchesTheExactDistance) {
  SphereSampler rng(606);
  IpoptLocalSolver ipopt;
  SolverSettings s;
  int separated = 0;
  for (int k = 0; k < 40; ++k) {
    const testgen::PairCase c = testgen::paper_like_any(rng);
    SolverSettings e = s;
    e.method = Method::kExact;
    const SignedSolution exact = signed_distance(c.a, c.b, e, ipopt, std::nullopt);
    const SignedSolution m = signed_distance(c.a, c.b, s, ipopt, std::nullopt);
    const double size = (c.a.rowwise().maxCoeff() - c.a.rowwise().minCoeff()).norm();
    EXPECT_NEAR(m.value, exact.value, 1e-9 * size) << k;
    // Warm-started from a nearby direction: the same value.
    const SignedSolution w = signed_distance(
        c.a, c.b, s, ipopt, Vec3(m.direction + Vec3(0.05, -0.03, 0.02)).normalized());
    EXPECT_NEAR(w.value, exact.value, 1e-9 * size) << k;
    separated += exact.value < 0;
  }
  EXPECT_GT(separated, 5);  // the set holds both kinds
}
