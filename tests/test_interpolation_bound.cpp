// geometry/interpolation_bound.h against dense samples of exact surfaces.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "geometry/interpolation_bound.h"
#include "geometry/types.h"

namespace {

using pd::SecondDerivativeBounds;
using pd::Vec2;
using pd::Vec3;
using Surface = std::function<Vec3(double, double)>;

// The largest |S − L S| over a fine barycentric grid of the parameter triangle.
double sampled(const Surface& s, const std::array<Vec2, 3>& uv, int n = 60) {
  const Vec3 p[3] = {s(uv[0].x(), uv[0].y()), s(uv[1].x(), uv[1].y()), s(uv[2].x(), uv[2].y())};
  double worst = 0.0;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double a = double(i) / n, b = double(j) / n, c = 1.0 - a - b;
      const Vec2 q = a * uv[0] + b * uv[1] + c * uv[2];
      worst = std::max(worst, (s(q.x(), q.y()) - (a * p[0] + b * p[1] + c * p[2])).norm());
    }
  return worst;
}

TEST(InterpolationBound, SmallestEnclosingRadius) {
  // Right triangle: half the hypotenuse; acute: the circumradius; obtuse: half the longest side.
  EXPECT_NEAR(pd::smallest_enclosing_radius({0, 0}, {2, 0}, {0, 2}), std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(pd::smallest_enclosing_radius({0, 0}, {2, 0}, {1, std::sqrt(3.0)}),
              2.0 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(pd::smallest_enclosing_radius({0, 0}, {4, 0}, {2, 0.5}), 2.0, 1e-15);
  EXPECT_NEAR(pd::smallest_enclosing_radius({0, 0}, {4, 0}, {1, 0}), 2.0, 1e-15);  // flat
}

TEST(InterpolationBound, PlaneIsExact) {
  EXPECT_EQ(pd::triangle_interpolation_bound({Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)}, {}), 0.0);
}

// Random parameter triangles on a cylinder, a cone, a sphere and a torus (OCCT's
// parametrisations, radii over three decades): the bound holds, and is within
// a few times the true chord error (it is the error's order, not a loose cap).
TEST(InterpolationBound, HoldsAndIsTightOnAnalyticSurfaces) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (double r : {0.3, 5.0, 120.0}) {
    const double R = 3.0 * r, alpha = 0.4;
    struct Case {
      const char* name;
      Surface s;
      std::function<SecondDerivativeBounds(double, double)> m;  // over [v0, v1]
    };
    const Case cases[] = {
        {"cylinder", [&](double u, double v) { return Vec3(r * std::cos(u), r * std::sin(u), v); },
         [&](double, double) {
           return SecondDerivativeBounds{r, 0, 0};
         }},
        {"cone",
         [&](double u, double v) {
           const double rho = r + v * std::sin(alpha);
           return Vec3(rho * std::cos(u), rho * std::sin(u), v * std::cos(alpha));
         },
         [&](double v0, double v1) {
           return SecondDerivativeBounds{
               std::max(std::abs(r + v0 * std::sin(alpha)), std::abs(r + v1 * std::sin(alpha))),
               std::sin(alpha), 0};
         }},
        {"sphere",
         [&](double u, double v) {
           return Vec3(r * std::cos(v) * std::cos(u), r * std::cos(v) * std::sin(u),
                       r * std::sin(v));
         },
         [&](double, double) {
           return SecondDerivativeBounds{r, r, r};
         }},
        {"torus",
         [&](double u, double v) {
           const double rho = R + r * std::cos(v);
           return Vec3(rho * std::cos(u), rho * std::sin(u), r * std::sin(v));
         },
         [&](double, double) {
           return SecondDerivativeBounds{R + r, r, r};
         }},
    };
    for (const Case& c : cases)
      for (int k = 0; k < 40; ++k) {
        // Triangles as meshers make them: steps of a few degrees, lengths to scale.
        const double du = 0.02 + 0.3 * unit(rng),
                     dv =
                         (0.02 + 0.3 * unit(rng)) *
                         (std::string(c.name) == "cylinder" || std::string(c.name) == "cone" ? r
                                                                                             : 1.0);
        const double u = 6.0 * unit(rng), v = unit(rng);
        const std::array<Vec2, 3> uv = {Vec2(u, v), Vec2(u + du, v + dv * unit(rng)),
                                        Vec2(u + du * unit(rng), v + dv)};
        const double v0 = std::min({uv[0].y(), uv[1].y(), uv[2].y()});
        const double v1 = std::max({uv[0].y(), uv[1].y(), uv[2].y()});
        const double truth = sampled(c.s, uv);
        const double bound = pd::triangle_interpolation_bound(uv, c.m(v0, v1));
        EXPECT_GE(bound, truth * (1 - 1e-9)) << c.name << " r " << r;
        EXPECT_LE(bound, 4.0 * truth + 1e-12) << c.name << " r " << r;
        // Measured at 15 points, the remainder a sixteenth of the bound: within
        // a quarter of the truth (the coarse bound was within 4×).
        const Vec3 p[3] = {c.s(uv[0].x(), uv[0].y()), c.s(uv[1].x(), uv[1].y()),
                           c.s(uv[2].x(), uv[2].y())};
        const double sharp =
            pd::refined_interpolation_bound(uv, c.m(v0, v1), 4, [&](const Eigen::Vector3d& w) {
              const Vec2 q = w[0] * uv[0] + w[1] * uv[1] + w[2] * uv[2];
              return (c.s(q.x(), q.y()) - (w[0] * p[0] + w[1] * p[1] + w[2] * p[2])).norm();
            });
        EXPECT_GE(sharp, truth * (1 - 1e-9)) << c.name << " r " << r;
        EXPECT_LE(sharp, 1.25 * truth + 1e-12) << c.name << " r " << r;
      }
  }
}

// Corners stored off the surface (rounded, or a mesher's nodes): the measured
// errors carry the offsets, and the bound holds against the stored corners.
TEST(InterpolationBound, SharpBoundHoldsAgainstCornersOffTheSurface) {
  const double r = 5.0;
  const auto s = [&](double u, double v) {
    return Vec3(r * std::cos(v) * std::cos(u), r * std::cos(v) * std::sin(u), r * std::sin(v));
  };
  const std::array<Vec2, 3> uv = {Vec2(0.1, 0.2), Vec2(0.4, 0.25), Vec2(0.2, 0.5)};
  const Vec3 p[3] = {s(0.1, 0.2) + Vec3(1e-3, 0, 0), s(0.4, 0.25), s(0.2, 0.5) - Vec3(0, 0, 2e-3)};
  double truth = 0.0;
  for (int i = 0; i <= 60; ++i)
    for (int j = 0; i + j <= 60; ++j) {
      const double a = i / 60.0, b = j / 60.0, c = 1.0 - a - b;
      const Vec2 q = a * uv[0] + b * uv[1] + c * uv[2];
      truth = std::max(truth, (s(q.x(), q.y()) - (a * p[0] + b * p[1] + c * p[2])).norm());
    }
  const double sharp =
      pd::refined_interpolation_bound(uv, {r, r, r}, 4, [&](const Eigen::Vector3d& w) {
        const Vec2 q = w[0] * uv[0] + w[1] * uv[1] + w[2] * uv[2];
        return (s(q.x(), q.y()) - (w[0] * p[0] + w[1] * p[1] + w[2] * p[2])).norm();
      });
  EXPECT_GE(sharp, truth * (1 - 1e-9));
  EXPECT_GE(truth, 2e-3);  // the offsets are in it
  EXPECT_LE(sharp, truth + pd::triangle_interpolation_bound(uv, {r, r, r}) / 16 + 1e-12);
}

TEST(InterpolationBound, SegmentIsTheChordSagToSecondOrder) {
  // A circle of radius 10 in steps of 0.2 rad: sag r(1 − cos(θ/2)).
  const double r = 10.0, step = 0.2;
  const double sag = r * (1.0 - std::cos(step / 2));
  const double bound = pd::segment_interpolation_bound(1.0, 1.0 + step, r);
  EXPECT_GE(bound, sag);
  EXPECT_LE(bound, 1.01 * sag);
}

}  // namespace
