#include "geometry/frame.h"

#include <algorithm>
#include <cmath>

namespace pd {

Points Frame::to_local(const Points& world) const {
  return (world.colwise() - centre) / scale;
}

namespace {
Frame frame_of_box(const Vec3& lo, const Vec3& hi) {
  Frame f;
  // Halves first: hi − lo and lo + hi overflow beyond ~9e307, the halves never
  // do (and for every other box this is the same number, bit for bit).
  f.centre = 0.5 * lo + 0.5 * hi;
  const Vec3 half = 0.5 * hi - 0.5 * lo;
  double half_diag = half.norm();
  // The squares inside norm() overflow beyond ~1e154 and underflow below
  // ~1e-154; the scaled norm does neither.
  if (!(half_diag > 0 && std::isfinite(half_diag))) half_diag = half.stableNorm();
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
