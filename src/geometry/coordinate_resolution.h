// The resolution of a part's coordinates: the spacing of the numbers its
// vertices are stored in, at their magnitude, carried to scene units. A depth
// below it cannot be told from rounding (two touching float32 parts 35 m from
// the origin can overlap by 0.004 mm).
#pragma once

#include "geometry/types.h"

namespace pd {

/// The spacing of representable numbers next to |x| = `magnitude` (the unit in
/// the last place): 2^(e − 23) for float32, 2^(e − 52) for double, where
/// 2^e ≤ magnitude < 2^(e+1); the smallest normal's spacing for 0 and subnormals.
double coordinate_step(double magnitude, bool float32);

/// A part's coordinate resolution in scene units: the spacing at its largest
/// stored coordinate magnitude `max_abs` (file or inline units), times
/// `stretch`, the placement's largest stretch factor (units, then transform),
/// and no finer than the double spacing at its placed magnitude
/// `placed_max_abs` (the placement is computed in double).
double coordinate_resolution(double max_abs, bool float32, double stretch, double placed_max_abs);

/// The largest |coordinate| of a point set (0 for none).
double max_abs_coordinate(const Points& p);

}  // namespace pd
