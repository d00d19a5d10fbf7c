#include "scene/part_convexity.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "geometry/convexity.h"
#include "scene/convexity_cache.h"

namespace pd {

bool convexity_unmeasured(const Part& p) {
  return p.convexity_on_demand() && !p.convex && !p.error;
}

void measure_convexity(Part& p, const std::string& cache_dir) {
  PartSurface& s = *p.surface;
  // File units, at this part's stretch: voids count at its tolerance, and the
  // estimate stops once it is nonconvex for it (or beyond the noise).
  const double tol = s.concavity_tol / s.stretch, stop_above = std::max(tol, s.noise);
  const std::string key = convexity_key(s.file_hash, tol, stop_above);
  StoredConvexity c;
  if (auto hit = read_cached_convexity(cache_dir, key)) {
    c = *hit;
  } else {
    const std::shared_ptr<const Mesh> mesh = file_mesh_of(s);
    // The part's hull is its file's hull vertices placed: placed back, they
    // spare the estimate a qhull of every vertex.
    const Eigen::Matrix3d A = s.placement.topLeftCorner<3, 3>();
    Points hull_points;
    if (p.pieces.size() == 1 && A.determinant() != 0) {
      const Eigen::Matrix3d inv = A.inverse();
      hull_points = inv * (p.pieces[0].vertices.colwise() - s.placement.topRightCorner<3, 1>());
    }
    const ConvexityScreen screen =
        screen_convexity(*mesh, tol, stop_above, hull_points.cols() ? &hull_points : nullptr);
    c = {screen.concavity.value, screen.closed};
    write_cached_convexity(cache_dir, key, c);
  }
  p.convex = c.concavity <= stop_above;
  s.concavity = c.concavity * s.stretch;
  s.closed = c.closed;
}

}  // namespace pd
