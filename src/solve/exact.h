// The exact reference: the hull of the Minkowski difference M = {p_i − q_j}.
// The origin lies inside M exactly when the hulls overlap; the penetration depth
// is then the smallest facet offset of M and the direction that facet's normal.
// Otherwise the separation distance is the distance from the origin to M.
#pragma once

#include "geometry/types.h"
#include "solve/result.h"

namespace pd {

/// p, q in the pair's unit frame. Cost: O(nm log nm) (qhull on nm points).
DepthSolution exact_depth(const Points& p, const Points& q);

/// Closest point of triangle (a, b, c) to the origin.
Vec3 closest_point_on_triangle(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace pd
