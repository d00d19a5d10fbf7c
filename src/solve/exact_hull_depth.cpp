#include "solve/exact_hull_depth.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <cmath>
#include <set>

#include "tolerances.h"

namespace pd {

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;

constexpr int kRounds = 8;

Vector column(const Points& x, Eigen::Index k) {
  return {x(0, k), x(1, k), x(2, k)};
}

// The index of the column of x extreme in n (largest when top), exactly; the
// double pass keeps the candidates within a generous band (exact_facet.cpp).
Eigen::Index extreme(const Points& x, const Vector& n, const Vec3& unit, double size, bool top) {
  const Eigen::RowVectorXd s = unit.transpose() * x;
  const double e = top ? s.maxCoeff() : s.minCoeff();
  Eigen::Index best = -1;
  K::FT best_v;
  for (Eigen::Index k = 0; k < s.size(); ++k) {
    if (top ? s[k] < e - 1e-13 * size : s[k] > e + 1e-13 * size) continue;
    const K::FT v = n * column(x, k);
    if (best < 0 || (top ? v > best_v : v < best_v)) best = k, best_v = v;
  }
  return best;
}

}  // namespace

std::optional<ExactFacet> exact_hull_depth(const Points& a, const Points& b,
                                           const std::vector<MinkowskiIndex>& vertices) {
  std::set<std::pair<int, int>> ids;
  for (const MinkowskiIndex& v : vertices) ids.insert({v.i, v.j});
  const double size = std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff());
  for (int round = 0; round < kRounds; ++round) {
    std::vector<Point> pts;
    for (const auto& [i, j] : ids) pts.push_back(CGAL::ORIGIN + (column(a, i) - column(b, j)));
    Mesh hull;
    CGAL::convex_hull_3(pts.begin(), pts.end(), hull);
    if (hull.number_of_faces() < 4) return std::nullopt;  // flat
    // The nearest facet plane, every facet with the origin strictly inside.
    K::FT best = -1, best_d;
    Vector best_n;
    for (auto f : hull.faces()) {
      auto h = hull.halfedge(f);
      const Point& x0 = hull.point(hull.target(h));
      const Point& x1 = hull.point(hull.target(hull.next(h)));
      const Point& x2 = hull.point(hull.target(hull.next(hull.next(h))));
      const Vector n = CGAL::cross_product(x1 - x0, x2 - x0);
      const K::FT d = n * (x0 - CGAL::ORIGIN);
      if (!(d > 0)) return std::nullopt;
      const K::FT d2 = d * d / n.squared_length();
      if (best < 0 || d2 < best) best = d2, best_n = n, best_d = d;
    }
    const Vec3 unit =
        Vec3(CGAL::to_double(best_n.x()), CGAL::to_double(best_n.y()), CGAL::to_double(best_n.z()))
            .normalized();
    const Eigen::Index i = extreme(a, best_n, unit, size, true);
    const Eigen::Index j = extreme(b, best_n, unit, size, false);
    if (best_n * (column(a, i) - column(b, j)) <= best_d) {
      ExactFacet out;
      out.depth = std::sqrt(CGAL::to_double(CGAL::exact(best)));
      out.direction = unit;
      return out;
    }
    if (!ids.insert({static_cast<int>(i), static_cast<int>(j)}).second) return std::nullopt;
  }
  return std::nullopt;
}

std::optional<ExactFacet> exact_bracket_depth(const Points& a, const Points& b,
                                              const DepthBracket& bracket, double scale) {
  if (bracket.near_faces.empty()) return std::nullopt;
  // The faces beyond the band are farther than nearest_low + 3·kEpaRounding
  // (epa.h); the bound passed keeps one kEpaRounding for the scaling's rounding.
  if (auto e = exact_facet_depth(a, b, bracket.near_faces,
                                 (bracket.nearest_low + 2 * tol::kEpaRounding) * scale))
    return e;
  return exact_hull_depth(a, b, bracket.vertices);
}

}  // namespace pd
