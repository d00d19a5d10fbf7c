// max_min_affine and the cheaper min_max_affine against the exact LP optimum
// found by enumerating vertices.
#include <gtest/gtest.h>

#include <random>

#include "lp_reference.h"
#include "solve/max_min_affine.h"

namespace pd {
namespace {

TEST(MaxMinAffine, EqualsTheExactOptimumOnRandomProblems) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 300; ++trial) {
    const int m = 1 + trial % 6;
    std::vector<Affine> f(m);
    for (Affine& g : f) {
      g.value = 3 * u(rng);
      g.slope = Vec3(u(rng), u(rng), u(rng)) * (trial % 3 == 0 ? 10.0 : 1.0);
    }
    const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    const Vec3 lo = a.cwiseMin(b), hi = a.cwiseMax(b);
    const double exact = max_min_affine_reference(f, lo, hi);
    const double bound = max_min_affine(f, lo, hi);
    EXPECT_GE(bound, exact - 1e-12) << "trial " << trial;                         // sound
    EXPECT_LE(bound, exact + 1e-9 * (1 + std::abs(exact))) << "trial " << trial;  // tight
    // The cheap bound is one too, and the LP never exceeds it (the thickness
    // skips the LP of a choice whose cheap bound is below what it has).
    const double cheap = min_max_affine(f, lo, hi);
    EXPECT_GE(cheap, exact - 1e-12) << "trial " << trial;
    EXPECT_LE(bound, cheap + 1e-9 * (1 + std::abs(cheap))) << "trial " << trial;
    if (m == 1) {
      EXPECT_NEAR(cheap, exact, 1e-12 * (1 + std::abs(exact))) << "trial " << trial;
    }
  }
}

// The plane models of a pin seated in its bore: up to 24 functions, the
// facets' planes of two coaxial polygons (the pin's inside distance and the
// bore's), degenerate as CAD's are (parallel and opposed planes, ties).
TEST(MaxMinAffine, EqualsTheExactOptimumOnAPinInItsBore) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 18; ++trial) {  // each facet count twice
    const int facets = 4 + trial % 9;         // per surface: 8 to 24 functions
    const double pin = 5.0, bore = 5.0 + 0.01 * (trial % 4) - 0.005;
    std::vector<Affine> f;
    for (int k = 0; k < facets; ++k) {
      const double a = 2 * M_PI * (k + 0.5 * (trial % 2)) / facets;
      const Vec3 n(std::cos(a), std::sin(a), 0);
      f.push_back({pin, -n});   // inside the pin: pin − n·x
      f.push_back({-bore, n});  // inside the bore's part: n·x − bore
    }
    const Vec3 c = 5 * Vec3(std::cos(u(rng) * M_PI), std::sin(u(rng) * M_PI), u(rng));
    const Vec3 e = Vec3(0.3, 0.3, 2) * (0.5 + 0.5 * std::abs(u(rng)));
    const double exact = max_min_affine_reference(f, c - e, c + e);
    const double bound = max_min_affine(f, c - e, c + e);
    EXPECT_GE(bound, exact - 1e-12) << "trial " << trial;
    EXPECT_LE(bound, exact + 1e-9 * (1 + std::abs(exact))) << "trial " << trial;
  }
}

TEST(MaxMinAffine, TwoOpposedPlanesGiveHalfTheirGapWhateverTheBox) {
  // s1 = x (inside above x = 0), s2 = 0.3 − x: min ≤ 0.15 everywhere.
  const std::vector<Affine> f{{0.0, Vec3(1, 0, 0)}, {0.3, Vec3(-1, 0, 0)}};
  EXPECT_NEAR(max_min_affine(f, Vec3(-50, -50, -50), Vec3(50, 50, 50)), 0.15, 1e-12);
  EXPECT_NEAR(max_min_affine(f, Vec3(0.2, 0, 0), Vec3(5, 1, 1)), 0.1, 1e-12);
}

}  // namespace
}  // namespace pd
