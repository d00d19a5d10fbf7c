#include "corpus/exact_reference.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <cmath>
#include <set>
#include <vector>

#include "geometry/hull.h"

namespace pd::testgen {

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

// The differences that go into the exact hull, as (i, j): all of them for small
// pairs; above the limit, those qhull keeps as hull vertices of the rounded
// differences (the others are interior, or within qhull's rounding of M's boundary).
std::vector<std::pair<int, int>> hull_candidates(const Points& a, const Points& b, bool& all) {
  const Eigen::Index n = a.cols(), m = b.cols();
  std::vector<std::pair<int, int>> ids;
  all = static_cast<std::size_t>(n * m) <= kExactReferencePoints;
  if (all) {
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < m; ++j) ids.emplace_back(i, j);
    return ids;
  }
  Points d(3, n * m);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < m; ++j) d.col(i * m + j) = a.col(i) - b.col(j);
  HullFacets f;
  if (!hull_facets(d, f)) {
    all = true;  // flat to rounding: every difference, the exact hull decides
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < m; ++j) ids.emplace_back(i, j);
    return ids;
  }
  std::set<int> keep;
  for (const auto& t : f.triangles) keep.insert(t.begin(), t.end());
  for (int k : keep) ids.emplace_back(k / static_cast<int>(m), k % static_cast<int>(m));
  return ids;
}

// All points on one plane (or line, or point), exactly.
bool flat(const std::vector<Point>& pts) {
  size_t k = 1;
  while (k < pts.size() && pts[k] == pts[0]) ++k;
  if (k == pts.size()) return true;
  const size_t second = k;
  while (k < pts.size() && CGAL::collinear(pts[0], pts[second], pts[k])) ++k;
  if (k == pts.size()) return true;
  const size_t third = k;
  for (; k < pts.size(); ++k)
    if (!CGAL::coplanar(pts[0], pts[second], pts[third], pts[k])) return false;
  return true;
}

}  // namespace

ExactReference exact_reference_depth(const Points& a, const Points& b) {
  ExactReference out;
  std::vector<Point> pts;
  for (const auto& [i, j] : hull_candidates(a, b, out.all_points)) {
    // Exact differences: Epeck's point minus vector is an exact construction.
    const Point pa(a(0, i), a(1, i), a(2, i));
    pts.push_back(pa - K::Vector_3(b(0, j), b(1, j), b(2, j)));
  }
  if (flat(pts)) return out;  // no interior: the hulls cannot interpenetrate
  Mesh hull;
  CGAL::convex_hull_3(pts.begin(), pts.end(), hull);
  if (CGAL::is_empty(hull) || hull.number_of_faces() == 0) return out;  // flat
  // The nearest facet plane: exact squared distances D² / |N|² of the origin,
  // every facet's origin side exact (outward normal N, offset D = N·x).
  const Point origin(CGAL::ORIGIN);
  K::FT best = -1;
  K::Vector_3 best_n;
  for (auto f : hull.faces()) {
    auto h = hull.halfedge(f);
    const Point& x0 = hull.point(hull.target(h));
    const Point& x1 = hull.point(hull.target(hull.next(h)));
    const Point& x2 = hull.point(hull.target(hull.next(hull.next(h))));
    const K::Vector_3 n = CGAL::cross_product(x1 - x0, x2 - x0);
    const K::FT d = n * (x0 - origin);
    if (!(d > 0)) return out;  // the origin is on or outside this facet: depth 0
    const K::FT d2 = d * d / n.squared_length();
    if (best < 0 || d2 < best) {
      best = d2;
      best_n = n;
    }
  }
  out.depth = std::sqrt(CGAL::to_double(CGAL::exact(best)));
  const Vec3 n(CGAL::to_double(best_n.x()), CGAL::to_double(best_n.y()),
               CGAL::to_double(best_n.z()));
  out.direction = n.normalized();
  return out;
}

}  // namespace pd::testgen
