#include "geometry/frame.h"

#include <algorithm>

namespace pd {

Points Frame::to_local(const Points& world) const {
  return (world.colwise() - centre) / scale;
}

namespace {
Frame frame_of_box(const Vec3& lo, const Vec3& hi) {
  Frame f;
  f.centre = 0.5 * (lo + hi);
  const double half_diag = 0.5 * (hi - lo).norm();
  // A single point (or an empty set) has no size; any positive scale works.
  const double largest = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
  f.scale = half_diag > 0 ? half_diag : (largest > 0 ? largest : 1.0);
  return f;
}
}  // namespace

Frame pair_frame(const Points& a, const Points& b) {
  Vec3 lo = a.rowwise().minCoeff().cwiseMin(b.rowwise().minCoeff());
  Vec3 hi = a.rowwise().maxCoeff().cwiseMax(b.rowwise().maxCoeff());
  return frame_of_box(lo, hi);
}

Frame points_frame(const Points& a) {
  return frame_of_box(a.rowwise().minCoeff(), a.rowwise().maxCoeff());
}

}  // namespace pd
