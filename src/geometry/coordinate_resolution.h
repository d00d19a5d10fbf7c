// The rounding step of a part's coordinates as stored: what no geometric
// measurement of the part can resolve below (docs/numerics.md).
#pragma once

#include "geometry/types.h"

namespace pd {

/// How a part's coordinates were stored before pdcheck read them as doubles.
enum class CoordinateStorage { kFloat32, kDouble };

/// The spacing of representable numbers at the largest |coordinate| of
/// `points` in the given storage: one float32 step (2^-23 of the magnitude's
/// power of two) for mesh files, which assimp hands over as float32, one double
/// step for inline vertices. A coordinate stored so is within half of it of
/// the value its writer meant, so two parts' stored surfaces may cross by up to
/// the sum of their steps. 0 for an empty set.
double coordinate_resolution(const Points& points, CoordinateStorage storage);

}  // namespace pd
