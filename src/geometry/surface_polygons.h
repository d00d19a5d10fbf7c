// Convex planar polygons known to lie on a part's surface (its faces, or
// faces clipped to a cell), found by point: a concavity sample inside one of
// them is on the part, so its distance need not be measured. A uniform grid
// over the polygons' boxes. One object per thread: covers() remembers the last
// polygon it found.
#pragma once

#include <array>
#include <unordered_map>
#include <utility>
#include <vector>

#include "geometry/types.h"

namespace pd {

class SurfacePolygons {
 public:
  /// Polygon k has the corners `corners.col(ranges[k].first … ranges[k].second − 1)`,
  /// in order around it. Degenerate polygons, and polygons spanning too many
  /// grid cells, are left out (their points are measured as any other).
  SurfacePolygons(Points corners, const std::vector<std::pair<long, long>>& ranges, double within);

  /// True when x lies within `within` of one of the polygons (so within it of
  /// the part). False says nothing.
  bool covers(const Vec3& x) const;

 private:
  struct Polygon {
    Vec3 normal;  ///< unit, oriented by the corners' order
    double offset = 0.0;
    long first = 0, last = 0;
  };
  using Cell = std::array<long long, 3>;
  struct CellHash {
    std::size_t operator()(const Cell& c) const {
      return std::size_t(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL);
    }
  };
  Cell cell_of(const Vec3& x) const;
  bool may_meet(const Polygon& g, const Cell& c) const;
  bool inside(const Polygon& g, const Vec3& x) const;

  Points corners_;
  double within_;
  double size_ = 1.0;  ///< grid spacing
  std::vector<Polygon> polygons_;
  std::unordered_map<Cell, std::vector<int>, CellHash> grid_;
  mutable int last_ = -1;  ///< the polygon that covered the previous point (lattices are runs)
};

}  // namespace pd
