// Axis-aligned bounding boxes, for the broad phase.
#pragma once

#include "geometry/types.h"

namespace pd {

struct Aabb {
  Vec3 lo = Vec3::Constant(0.0);
  Vec3 hi = Vec3::Constant(0.0);

  static Aabb of(const Points& pts);
  Aabb inflated(double margin) const { return {lo.array() - margin, hi.array() + margin}; }
  /// Closed-box test: boxes that share only a face still overlap (touching parts
  /// must reach the narrow phase, which decides between touching and separated).
  bool overlaps(const Aabb& o) const {
    return (lo.array() <= o.hi.array()).all() && (o.lo.array() <= hi.array()).all();
  }
  Aabb merged(const Aabb& o) const { return {lo.cwiseMin(o.lo), hi.cwiseMax(o.hi)}; }
};

}  // namespace pd
