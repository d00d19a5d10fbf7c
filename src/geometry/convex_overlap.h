// The intersection of two convex point sets' hulls.
#pragma once

#include <optional>

#include "geometry/hull.h"
#include "geometry/types.h"

namespace pd {

/// A ∩ B of two convex point sets' hulls, as a hull (dimension 3); nullopt when
/// they do not overlap in a solid (touching, or apart). Exact up to rounding:
/// every vertex of the intersection is an end of one hull's edge clipped to the
/// other hull.
std::optional<Hull> convex_overlap(const Points& a, const Points& b);

}  // namespace pd
