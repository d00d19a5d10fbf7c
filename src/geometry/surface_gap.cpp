#include "geometry/surface_gap.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pd {

namespace {

// The squared distance between segments [p1, q1] and [p2, q2] (Ericson 5.1.9,
// with degenerate segments handled).
double segment_distance2(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  const double tiny = std::numeric_limits<double>::min();
  double s = 0.0, t = 0.0;
  if (a <= tiny && e <= tiny) return r.squaredNorm();
  if (a <= tiny) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= tiny) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return (p1 + d1 * s - (p2 + d2 * t)).squaredNorm();
}

}  // namespace

double triangle_distance(const std::array<Vec3, 3>& p, const std::array<Vec3, 3>& q) {
  double best = INFINITY;
  for (int k = 0; k < 3; ++k) {
    best = std::min(best, (p[k] - closest_on_triangle(p[k], q[0], q[1], q[2])).squaredNorm());
    best = std::min(best, (q[k] - closest_on_triangle(q[k], p[0], p[1], p[2])).squaredNorm());
    for (int j = 0; j < 3; ++j)
      best = std::min(best, segment_distance2(p[k], p[(k + 1) % 3], q[j], q[(j + 1) % 3]));
  }
  return std::sqrt(best);
}

double surface_gap_lower_bound(const std::vector<std::array<Vec3, 3>>& a,
                               const std::vector<std::array<Vec3, 3>>& b, const TriangleTree& tree,
                               double enough, double useless) {
  if (a.empty() || b.empty()) return enough;
  // A distance computed from coordinates of magnitude m is within a few ulps
  // of m of the true one.
  double scale = 0.0;
  for (const auto* set : {&a, &b})
    for (const auto& t : *set)
      for (const Vec3& v : t) scale = std::max(scale, v.cwiseAbs().maxCoeff());
  const double rounding = 64.0 * std::numeric_limits<double>::epsilon() * std::max(scale, 1.0);
  const Vec3 pad = Vec3::Constant(enough);
  double gap = enough;
  using Tri = std::array<Vec3, 3>;
  std::vector<int> near;
  for (const Tri& t : a) {
    const Vec3 lo = t[0].cwiseMin(t[1]).cwiseMin(t[2]) - pad;
    const Vec3 hi = t[0].cwiseMax(t[1]).cwiseMax(t[2]) + pad;
    near.clear();
    tree.in_turned_box(Eigen::Matrix3d::Identity(), Vec3::Zero(), lo, hi, near);
    for (int j : near) {
      const Tri& q = b[size_t(j)];
      // Boxes apart by at least the gap found: the triangles too.
      const Vec3 qlo = q[0].cwiseMin(q[1]).cwiseMin(q[2]), qhi = q[0].cwiseMax(q[1]).cwiseMax(q[2]);
      const Vec3 apart = (qlo - (hi - pad)).cwiseMax((lo + pad) - qhi).cwiseMax(0.0);
      if (apart.norm() - rounding >= gap) continue;
      gap = std::min(gap, std::max(0.0, triangle_distance(t, q) - rounding));
      if (gap <= useless) return 0.0;
    }
  }
  return gap;
}

}  // namespace pd
