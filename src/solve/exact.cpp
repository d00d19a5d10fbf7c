#include "solve/exact.h"

#include <Eigen/Eigenvalues>
#include <limits>

#include "geometry/hull.h"
#include "tolerances.h"

namespace pd {

Vec3 closest_point_on_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  // Ericson, Real-Time Collision Detection, 5.1.5, with the query point at 0.
  const Vec3 ab = b - a, ac = c - a, ap = -a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = -b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = -c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

namespace {

Points minkowski_difference(const Points& p, const Points& q) {
  Points m(3, p.cols() * q.cols());
  Eigen::Index k = 0;
  for (Eigen::Index i = 0; i < p.cols(); ++i)
    for (Eigen::Index j = 0; j < q.cols(); ++j) m.col(k++) = p.col(i) - q.col(j);
  return m;
}

// Closest point to the origin of the hull of a set whose hull is flat or lower
// dimensional. Such an M has no interior, so the pair cannot interpenetrate.
Vec3 closest_point_degenerate(const Points& m) {
  const Hull h = convex_hull(m);
  const Points& v = h.vertices;
  if (h.dimension == 0) return v.col(0);
  if (h.dimension == 1) {
    const Vec3 a = v.col(0), d = v.col(1) - v.col(0);
    const double t = std::clamp(-a.dot(d) / d.squaredNorm(), 0.0, 1.0);
    return a + t * d;
  }
  // A convex polygon: fan triangles from its first vertex, best closest point.
  // (qhull returns the polygon's vertices unordered; order them by angle first.)
  const Vec3 centre = v.rowwise().mean();
  const Points c = v.colwise() - centre;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(c * c.transpose());
  const Vec3 e1 = eig.eigenvectors().col(2), e2 = eig.eigenvectors().col(1);
  std::vector<std::pair<double, int>> order;
  for (int k = 0; k < v.cols(); ++k)
    order.emplace_back(std::atan2(c.col(k).dot(e2), c.col(k).dot(e1)), k);
  std::sort(order.begin(), order.end());
  Vec3 best = v.col(order[0].second);
  for (size_t k = 1; k + 1 < order.size(); ++k) {
    const Vec3 x = closest_point_on_triangle(v.col(order[0].second), v.col(order[k].second),
                                             v.col(order[k + 1].second));
    if (x.squaredNorm() < best.squaredNorm()) best = x;
  }
  return best;
}

DepthSolution separated_solution(const Vec3& closest) {
  DepthSolution s;
  const double d = closest.norm();
  s.depth = 0.0;
  s.distance = d;
  // −z* points from a to b (see docs/report-format.md); touching has no normal.
  if (d > 0) s.direction = -closest / d;
  return s;
}

}  // namespace

DepthSolution exact_depth(const Points& p, const Points& q) {
  const Points m = minkowski_difference(p, q);
  HullFacets f;
  if (!hull_facets(m, f)) return separated_solution(closest_point_degenerate(m));

  // Inside iff every facet has the origin strictly on its inner side.
  double depth = std::numeric_limits<double>::infinity();
  size_t best = 0;
  for (size_t k = 0; k < f.offsets.size(); ++k) {
    if (-f.offsets[k] < depth) {
      depth = -f.offsets[k];
      best = k;
    }
  }
  // Contact within rounding is reported as depth 0 with the contact facet's
  // normal (the direction of a tiny closest point would be noise).
  if (depth > -tol::kTouch) {
    DepthSolution s;
    s.depth = depth > tol::kGapRounding ? depth : 0.0;  // touching; never -0
    s.direction = f.normals[best];
    s.distance = 0.0;
    return s;
  }
  Vec3 closest = Vec3::Zero();
  double best_d2 = std::numeric_limits<double>::infinity();
  for (const auto& t : f.triangles) {
    const Vec3 x = closest_point_on_triangle(m.col(t[0]), m.col(t[1]), m.col(t[2]));
    if (x.squaredNorm() < best_d2) {
      best_d2 = x.squaredNorm();
      closest = x;
    }
  }
  return separated_solution(closest);
}

}  // namespace pd
