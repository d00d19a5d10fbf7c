// geometry/spline_bound.h against the second derivatives of B-splines
// evaluated directly (Cox-de Boor), on random nets and knot vectors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "geometry/spline_bound.h"

namespace {

using pd::Vec3;

// N_{i,p}(t) on knots k (Cox-de Boor; 0/0 = 0), the last knot included.
double basis(const std::vector<double>& k, int i, int p, double t) {
  if (p == 0) {
    const bool last = t == k.back() && k[size_t(i + 1)] == k.back() && k[size_t(i)] < k.back();
    return (k[size_t(i)] <= t && t < k[size_t(i + 1)]) || last ? 1.0 : 0.0;
  }
  double out = 0.0;
  const double a = k[size_t(i + p)] - k[size_t(i)], b = k[size_t(i + p + 1)] - k[size_t(i + 1)];
  if (a > 0) out += (t - k[size_t(i)]) / a * basis(k, i, p - 1, t);
  if (b > 0) out += (k[size_t(i + p + 1)] - t) / b * basis(k, i + 1, p - 1, t);
  return out;
}

Vec3 curve(const pd::SplineCurve& c, double t) {
  Vec3 x = Vec3::Zero();
  for (size_t i = 0; i < c.poles.size(); ++i) x += basis(c.knots, int(i), c.degree, t) * c.poles[i];
  return x;
}

// A clamped knot vector of n poles and degree p, interior knots random (some repeated).
std::vector<double> knots(int n, int p, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> inner;
  for (int i = 0; i < n - p - 1; ++i) inner.push_back(u(rng));
  std::sort(inner.begin(), inner.end());
  if (inner.size() > 2) inner[1] = inner[2];  // a double knot
  std::vector<double> k(size_t(p) + 1, 0.0);
  k.insert(k.end(), inner.begin(), inner.end());
  k.resize(k.size() + size_t(p) + 1, 1.0);
  return k;
}

TEST(SplineBound, CurveSecondDerivativeHoldsOnEveryRange) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-10.0, 10.0), t01(0.0, 1.0);
  for (int p : {2, 3, 5}) {
    pd::SplineCurve c;
    c.degree = p;
    const int n = 9;
    for (int i = 0; i < n; ++i) c.poles.emplace_back(u(rng), u(rng), u(rng));
    c.knots = knots(n, p, rng);
    for (int trial = 0; trial < 20; ++trial) {
      double a = t01(rng), b = t01(rng);
      if (a > b) std::swap(a, b);
      const double bound = pd::spline_second_derivative_bound(c, a, b);
      // Degree 2 with a double knot is a crease: no bound across it.
      const double crease = c.knots[size_t(p) + 2];  // the doubled interior knot
      if (p == 2 && a < crease && crease < b) {
        EXPECT_EQ(bound, std::numeric_limits<double>::infinity()) << "[" << a << ", " << b << "]";
        continue;
      }
      ASSERT_TRUE(std::isfinite(bound));
      double worst = 0.0;  // central second differences over [a, b]
      const double h = 1e-4;
      for (int s = 0; s <= 200; ++s) {
        const double t = std::clamp(a + (b - a) * s / 200.0, h, 1.0 - h);
        worst = std::max(worst,
                         ((curve(c, t + h) - 2 * curve(c, t) + curve(c, t - h)) / (h * h)).norm());
      }
      // A second difference straddling a C1 knot averages the two sides: still ≤ the bound.
      EXPECT_LE(worst, bound * (1 + 1e-3) + 1e-6)
          << "degree " << p << " [" << a << ", " << b << "]";
    }
  }
}

TEST(SplineBound, CreasesHaveNoBoundAcrossThem) {
  // A polyline (degree 1) bends at every interior knot; a span between knots is straight.
  const pd::SplineCurve line{{{0, 0, 0}, {1, 1, 0}, {2, 0, 0}}, {0, 0, 0.5, 1, 1}, 1};
  EXPECT_EQ(pd::spline_second_derivative_bound(line, 0.4, 0.6),
            std::numeric_limits<double>::infinity());
  EXPECT_EQ(pd::spline_second_derivative_bound(line, 0.1, 0.5), 0.0);
  // A cubic with a triple knot: C0 there. Its chord across the crease is off
  // by far more than any bound built from the pieces' curvature.
  const pd::SplineCurve cubic{
      {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {2, 2, 0}, {2, 3, 0}, {2, 4, 0}},
      {0, 0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1, 1},
      3};
  EXPECT_EQ(pd::spline_second_derivative_bound(cubic, 0.3, 0.7),
            std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isfinite(pd::spline_second_derivative_bound(cubic, 0.5, 0.7)));
  // The clamped ends are no creases, even where a range reaches past them by
  // rounding (a triangle's corner on the end of an extrusion's basis curve).
  EXPECT_TRUE(std::isfinite(pd::spline_second_derivative_bound(cubic, 0.6, 1.0 + 1e-12)));
  EXPECT_TRUE(std::isfinite(pd::spline_second_derivative_bound(cubic, -1e-12, 0.4)));
  EXPECT_EQ(pd::spline_second_derivative_bound(line, 0.6, 1.0 + 1e-12), 0.0);
  // A surface creased along u = 0.5 (degree 2, double knot): S_uu unbounded
  // across it, S_vv still bounded.
  pd::SplineSurface s;
  s.nu = 5;
  s.nv = 3;
  s.udegree = 2;
  s.vdegree = 2;
  s.uknots = {0, 0, 0, 0.5, 0.5, 1, 1, 1};
  s.vknots = {0, 0, 0, 1, 1, 1};
  for (int i = 0; i < s.nu; ++i)
    for (int j = 0; j < s.nv; ++j) s.poles.emplace_back(i, j, (i == 2) ? 1.0 : 0.0);
  const pd::SecondDerivativeBounds across = pd::spline_second_derivative_bounds(s, 0.4, 0.6, 0, 1);
  EXPECT_EQ(across.uu, std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isfinite(across.vv));
  EXPECT_TRUE(std::isfinite(pd::spline_second_derivative_bounds(s, 0.1, 0.5, 0, 1).uu));
}

TEST(SplineBound, SurfaceBoundsHoldAndRangesNarrowThem) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  pd::SplineSurface s;
  s.nu = 7;
  s.nv = 7;
  s.udegree = 3;
  s.vdegree = 3;  // double knots: C1, so the bounds hold across them
  for (int i = 0; i < s.nu * s.nv; ++i) s.poles.emplace_back(u(rng), u(rng), u(rng));
  s.uknots = knots(s.nu, s.udegree, rng);
  s.vknots = knots(s.nv, s.vdegree, rng);
  const auto at = [&](double x, double y) {
    Vec3 p = Vec3::Zero();
    for (int i = 0; i < s.nu; ++i)
      for (int j = 0; j < s.nv; ++j)
        p += basis(s.uknots, i, s.udegree, x) * basis(s.vknots, j, s.vdegree, y) *
             s.poles[size_t(i * s.nv + j)];
    return p;
  };
  const pd::SecondDerivativeBounds whole = pd::spline_second_derivative_bounds(s, 0, 1, 0, 1);
  const double h = 1e-4;
  pd::SecondDerivativeBounds seen;
  for (int a = 1; a < 40; ++a)
    for (int b = 1; b < 40; ++b) {
      const double x = a / 40.0, y = b / 40.0;
      seen.uu = std::max(seen.uu, ((at(x + h, y) - 2 * at(x, y) + at(x - h, y)) / (h * h)).norm());
      seen.vv = std::max(seen.vv, ((at(x, y + h) - 2 * at(x, y) + at(x, y - h)) / (h * h)).norm());
      seen.uv = std::max(
          seen.uv, ((at(x + h, y + h) - at(x + h, y - h) - at(x - h, y + h) + at(x - h, y - h)) /
                    (4 * h * h))
                       .norm());
    }
  EXPECT_LE(seen.uu, whole.uu * (1 + 1e-3));
  EXPECT_LE(seen.vv, whole.vv * (1 + 1e-3));
  EXPECT_LE(seen.uv, whole.uv * (1 + 1e-3));
  // Of the order of the truth, not a loose cap.
  EXPECT_LE(whole.uu, 20 * seen.uu);
  // A smaller range reads fewer control points: never a larger bound.
  const pd::SecondDerivativeBounds part =
      pd::spline_second_derivative_bounds(s, 0.1, 0.2, 0.3, 0.4);
  EXPECT_LE(part.uu, whole.uu);
  EXPECT_LE(part.uv, whole.uv);
  EXPECT_LE(part.vv, whole.vv);
}

}  // namespace

namespace {

// How far a spline piece lies from its chord, against dense samples.
double chord_deviation(const pd::SplineCurve& c, double a, double b) {
  const Vec3 p = curve(c, a), q = curve(c, b), d = (q - p).normalized();
  double worst = 0.0;
  for (int s = 0; s <= 400; ++s) {
    const Vec3 x = curve(c, a + (b - a) * s / 400.0) - p;
    const double along = std::clamp(x.dot(d), 0.0, (q - p).norm());
    worst = std::max(worst, (x - along * d).norm());
  }
  return worst;
}

TEST(SplineBound, ChordBoundReadsOnlyWhatLeavesTheChord) {
  const auto bound = [](const pd::SplineCurve& c) {
    return pd::chord_deviation_bound(pd::spline_derivative_nets(c, 0, 1), curve(c, 1) - curve(c, 0),
                                     1.0);
  };
  const auto full = [](const pd::SplineCurve& c) {
    return pd::segment_interpolation_bound(0, 1, pd::spline_second_derivative_bound(c, 0, 1));
  };
  // A straight line whose parameter runs unevenly: a large C'', none across.
  const pd::SplineCurve line{
      {{0, 0, 0}, {0.2, 0, 0}, {3, 0, 0}, {4, 0, 0}}, {0, 0, 0, 0, 1, 1, 1, 1}, 3};
  EXPECT_GT(full(line), 0.1);
  EXPECT_NEAR(bound(line), 0.0, 1e-12);
  // A bent curve running forward: its across part bounds it, within the truth.
  const pd::SplineCurve bent{
      {{0, 0, 0}, {0.2, 1, 0}, {3, 1, 0}, {4, 0, 0}}, {0, 0, 0, 0, 1, 1, 1, 1}, 3};
  EXPECT_LT(bound(bent), full(bent));
  EXPECT_LE(chord_deviation(bent, 0, 1), bound(bent) + 1e-12);
  // A curve that runs back beyond its chord's end (a hook): the backward
  // speed bounds how far; never above the full bound.
  const pd::SplineCurve hook{
      {{0, 0, 0}, {5, 1, 0}, {5, 2, 0}, {4, 2, 0}}, {0, 0, 0, 0, 1, 1, 1, 1}, 3};
  EXPECT_LE(bound(hook), full(hook));
  EXPECT_LE(chord_deviation(hook, 0, 1), bound(hook) + 1e-12);
  // A start that backs up a little (a fitted involute's first control point):
  // the across bound plus the small run back, below the full bound.
  const pd::SplineCurve backs{{{0, 0, 0}, {-0.05, 0.3, 0}, {1, 0.6, 0}, {4, 0.5, 0}, {6, 0, 0}},
                              {0, 0, 0, 0, 0.5, 1, 1, 1, 1},
                              3};
  EXPECT_LT(bound(backs), full(backs));
  EXPECT_LE(chord_deviation(backs, 0, 1), bound(backs) + 1e-12);
  // Random cubic pieces: the bound holds on every one.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int trial = 0; trial < 200; ++trial) {
    pd::SplineCurve c{{}, {0, 0, 0, 0, 1, 1, 1, 1}, 3};
    for (int i = 0; i < 4; ++i) c.poles.emplace_back(i + u(rng) * 0.4, u(rng), u(rng) * 0.2);
    EXPECT_LE(chord_deviation(c, 0, 1), bound(c) + 1e-12) << trial;
  }
}

}  // namespace
