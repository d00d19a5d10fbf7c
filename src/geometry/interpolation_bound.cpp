#include "geometry/interpolation_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pd {

double smallest_enclosing_radius(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double ab = (b - a).squaredNorm(), bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm();
  const double longest = std::max({ab, bc, ca});
  // Right or obtuse: the longest side's circle holds the third corner.
  if (2.0 * longest >= ab + bc + ca) return 0.5 * std::sqrt(longest);
  // Acute: the circumradius, abc / (4 · area).
  const double cross = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
  const double area = 0.5 * std::abs(cross);
  if (!(area > 0.0)) return 0.5 * std::sqrt(longest);
  return std::sqrt(ab * bc * ca) / (4.0 * area);
}

namespace {

// The largest second directional derivative in the scaled parameters (k·u, v):
// |a²S_uu/k² + 2ab S_uv/k + b²S_vv| ≤ [|a| |b|] Q [|a| |b|]ᵀ ≤ λ_max(Q) for a
// unit (a, b), Q = [[uu/k², uv/k], [uv/k, vv]] (non-negative entries).
double scaled_bound(const SecondDerivativeBounds& m, double k) {
  const double p = m.uu / (k * k), q = m.uv / k, r = m.vv;
  return 0.5 * (p + r) + std::sqrt(0.25 * (p - r) * (p - r) + q * q);
}

}  // namespace

double triangle_interpolation_bound(const std::array<Vec2, 3>& uv,
                                    const SecondDerivativeBounds& m) {
  if (m.uu <= 0.0 && m.uv <= 0.0 && m.vv <= 0.0) return 0.0;
  // Every scaling k of u gives a valid bound; the best lies where u and v weigh
  // alike. Decades over twelve orders first (the ends reach the limits where
  // one parameter's derivatives vanish, as a cylinder's v), then tenths of a
  // decade round the best: within 13 % of the optimum over k.
  const auto at = [&](double exponent) {
    const double k = std::pow(10.0, exponent);
    const Vec2 s(k, 1.0);
    const double r = smallest_enclosing_radius(uv[0].cwiseProduct(s), uv[1].cwiseProduct(s),
                                               uv[2].cwiseProduct(s));
    return 0.5 * scaled_bound(m, k) * r * r;
  };
  double best = std::numeric_limits<double>::infinity();
  int decade = 0;
  for (int e = -6; e <= 6; ++e) {
    const double b = at(e);
    if (b < best) best = b, decade = e;
  }
  for (int t = -9; t <= 9; ++t) best = std::min(best, at(decade + t / 10.0));
  return best;
}

double refined_interpolation_bound(const std::array<Vec2, 3>& uv, const SecondDerivativeBounds& m,
                                   int n,
                                   const std::function<double(const Eigen::Vector3d&)>& error) {
  n = std::max(n, 1);
  double measured = 0.0;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j)
      measured = std::max(measured, error(Eigen::Vector3d(i, j, n - i - j) / n));
  return measured + triangle_interpolation_bound(uv, m) / (double(n) * n);
}

double segment_interpolation_bound(double t0, double t1, double m) {
  const double d = t1 - t0;
  return m * d * d / 8.0;
}

}  // namespace pd
