#include "geometry/convex_overlap.h"

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

#include "tolerances.h"

namespace pd {

std::optional<Hull> convex_overlap(const Points& a, const Points& b) {
  if (a.cols() < 4 || b.cols() < 4) return std::nullopt;
  const Hull ha = convex_hull(a), hb = convex_hull(b);
  if (ha.dimension < 3 || hb.dimension < 3) return std::nullopt;
  HullFacets fa, fb;
  if (!hull_facets(ha.vertices, fa) || !hull_facets(hb.vertices, fb)) return std::nullopt;
  const double scale =
      std::max((ha.vertices.rowwise().maxCoeff() - ha.vertices.rowwise().minCoeff()).norm(),
               (hb.vertices.rowwise().maxCoeff() - hb.vertices.rowwise().minCoeff()).norm());
  const double eps = tol::kOnHull * std::max(1.0, scale);
  std::vector<Vec3> found;
  // Each edge of one hull, clipped to the other (Cyrus–Beck): what is left of it
  // lies in both; its ends are the intersection's vertices.
  auto clip_edges = [&](const Points& p, const HullFacets& own, const HullFacets& other) {
    std::set<std::pair<int, int>> edges;
    for (const auto& t : own.triangles)
      for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
    for (const auto& [i, j] : edges) {
      const Vec3 p0 = p.col(i), p1 = p.col(j);
      double t0 = 0.0, t1 = 1.0;
      bool inside = true;
      for (size_t f = 0; f < other.normals.size() && inside; ++f) {
        const double d0 = other.normals[f].dot(p0) + other.offsets[f];
        const double d1 = other.normals[f].dot(p1) + other.offsets[f];
        if (d0 > eps && d1 > eps)
          inside = false;
        else if (d0 > eps)
          t0 = std::max(t0, d0 / (d0 - d1));
        else if (d1 > eps)
          t1 = std::min(t1, d0 / (d0 - d1));
        if (t0 > t1) inside = false;
      }
      if (!inside) continue;
      found.push_back(p0 + t0 * (p1 - p0));
      found.push_back(p0 + t1 * (p1 - p0));
    }
  };
  clip_edges(ha.vertices, fa, fb);
  clip_edges(hb.vertices, fb, fa);
  if (found.size() < 4) return std::nullopt;
  Points pts(3, static_cast<long>(found.size()));
  for (size_t k = 0; k < found.size(); ++k) pts.col(static_cast<long>(k)) = found[k];
  Hull overlap = convex_hull(pts);
  if (overlap.dimension < 3) return std::nullopt;
  return overlap;
}

}  // namespace pd
