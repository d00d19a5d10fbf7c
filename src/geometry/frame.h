// A similarity frame x' = (x - centre) / scale, used to solve every pair in
// coordinates of order one: depths and tolerances then mean the same thing
// for a 1 mm pin and a 10 m panel, and rounding stays at the level of 1e-16.
#pragma once

#include "geometry/types.h"

namespace pd {

struct Frame {
  Vec3 centre = Vec3::Zero();
  double scale = 1.0;  ///< > 0; a length L in world units is L / scale in the frame.

  Points to_local(const Points& world) const;
  Vec3 to_local(const Vec3& world) const { return (world - centre) / scale; }
  double length_to_world(double local) const { return local * scale; }
};

/// The frame of a pair: centred on the middle of the joint bounding box and
/// scaled by its half-diagonal, so both point sets lie in the unit ball.
Frame pair_frame(const Points& a, const Points& b);

/// The frame of one point set (same rule).
Frame points_frame(const Points& a);

}  // namespace pd
