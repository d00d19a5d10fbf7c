#include "geometry/surface_polygons.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace pd {

namespace {

// A polygon meeting more cells than this is left out: inserting it would cost
// more than measuring its points. Its box is walked cell by cell up to
// kMaxBoxCells (a long sliver placed askew, as CAD shafts' faces are, has a
// box of a thousand cells and meets a few dozen).
constexpr long long kMaxCells = 512;
constexpr long long kMaxBoxCells = 1 << 15;

}  // namespace

SurfacePolygons::SurfacePolygons(Points corners_in,
                                 const std::vector<std::pair<long, long>>& ranges, double within)
    : corners_(std::move(corners_in)), within_(within) {
  const Points& corners = corners_;
  double area = 0.0;
  for (const auto& [b, e] : ranges) {
    if (e - b < 3) continue;
    // Newell's normal: robust for any planar polygon, oriented by its order.
    Vec3 n = Vec3::Zero();
    for (long i = b; i < e; ++i) n += corners.col(i).cross(corners.col(i + 1 < e ? i + 1 : b));
    const double twice_area = n.norm();
    if (!(twice_area > 0)) continue;
    n /= twice_area;
    Polygon g{n, n.dot(corners.col(b)), b, e};
    // Planar to within the tolerance, or not used.
    bool flat = true;
    for (long i = b; i < e && flat; ++i)
      flat = std::abs(n.dot(corners.col(i)) - g.offset) <= within / 2;
    if (!flat) continue;
    polygons_.push_back(g);
    area += twice_area / 2;
  }
  if (polygons_.empty()) return;
  size_ = std::max(std::sqrt(area / static_cast<double>(polygons_.size())), 4.0 * within);
  if (!(size_ > 0) || !std::isfinite(size_)) {
    polygons_.clear();
    return;
  }
  for (int k = 0; k < static_cast<int>(polygons_.size()); ++k) {
    const Polygon& g = polygons_[k];
    Vec3 lo = corners.col(g.first), hi = lo;
    for (long i = g.first; i < g.last; ++i) {
      lo = lo.cwiseMin(corners.col(i));
      hi = hi.cwiseMax(corners.col(i));
    }
    const Cell a = cell_of(lo - Vec3::Constant(within)), z = cell_of(hi + Vec3::Constant(within));
    if ((z[0] - a[0] + 1) * (z[1] - a[1] + 1) * (z[2] - a[2] + 1) > kMaxBoxCells) continue;
    std::vector<Cell> cells;
    for (long long x = a[0]; x <= z[0] && cells.size() <= kMaxCells; ++x)
      for (long long y = a[1]; y <= z[1]; ++y)
        for (long long w = a[2]; w <= z[2]; ++w)
          if (may_meet(g, {x, y, w})) cells.push_back({x, y, w});
    if (cells.size() > kMaxCells) continue;
    for (const Cell& c : cells) grid_[c].push_back(k);
  }
}

// Whether points within `within` of polygon g may lie in cell c: the cell,
// grown by `within`, against the polygon's plane and the outer side of each of
// its edges (separating axes; a few cells too many may pass, none it meets
// fails). Rounding is covered by a margin of 1e-9 of the cell.
bool SurfacePolygons::may_meet(const Polygon& g, const Cell& c) const {
  const Vec3 centre = (Vec3(c[0], c[1], c[2]) + Vec3::Constant(0.5)) * size_;
  const double half = size_ / 2 + within_, slack = 1e-9 * size_;
  // How far the grown cell reaches along a unit direction u from its centre.
  const auto reach = [&](const Vec3& u) { return half * u.cwiseAbs().sum() + slack; };
  if (std::abs(g.normal.dot(centre) - g.offset) > reach(g.normal)) return false;
  for (long i = g.first; i < g.last; ++i) {
    const Vec3 a = corners_.col(i), b = corners_.col(i + 1 < g.last ? i + 1 : g.first);
    const Vec3 m = g.normal.cross(b - a);  // points into the polygon
    const double length = m.norm();
    if (!(length > 0)) continue;
    if ((m / length).dot(centre - a) < -reach(m / length)) return false;
  }
  return true;
}

SurfacePolygons::Cell SurfacePolygons::cell_of(const Vec3& x) const {
  return {static_cast<long long>(std::floor(x.x() / size_)),
          static_cast<long long>(std::floor(x.y() / size_)),
          static_cast<long long>(std::floor(x.z() / size_))};
}

// Within within/2 of the polygon's plane and inside every edge (no slack: at
// a sharp corner a slack would reach far beyond it): then within within/2 of
// the point of the polygon below x.
bool SurfacePolygons::inside(const Polygon& g, const Vec3& x) const {
  if (std::abs(g.normal.dot(x) - g.offset) > within_ / 2) return false;
  for (long i = g.first; i < g.last; ++i) {
    const Vec3 a = corners_.col(i), b = corners_.col(i + 1 < g.last ? i + 1 : g.first);
    const Vec3 edge = b - a;
    // Which side of the edge's line x lies on, within the plane (inside >= 0).
    if (g.normal.cross(edge).dot(x - a) < 0) return false;
  }
  return true;
}

bool SurfacePolygons::covers(const Vec3& x) const {
  if (polygons_.empty() || !x.allFinite()) return false;
  if (last_ >= 0 && inside(polygons_[last_], x)) return true;
  const auto it = grid_.find(cell_of(x));
  if (it == grid_.end()) return false;
  for (int k : it->second)
    if (k != last_ && inside(polygons_[k], x)) {
      last_ = k;
      return true;
    }
  return false;
}

}  // namespace pd
