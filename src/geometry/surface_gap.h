// A certified lower bound of the distance between two triangle surfaces that
// do not meet, for telling whether two meshes are farther apart than a given
// gap (B-rep pairs: farther than their sags, the solids are apart too).
#pragma once

#include <array>
#include <vector>

#include "geometry/triangle_tree.h"

namespace pd {

/// The distance between two triangles that do not cross: the least of their
/// corners' distances to the other triangle and of their edges' distances to
/// each other (Ericson, Real-Time Collision Detection, 5.1.9).
double triangle_distance(const std::array<Vec3, 3>& p, const std::array<Vec3, 3>& q);

/// min(enough, the distance between the triangles `a` and the triangles `b`
/// (which `tree` holds) less their coordinates' rounding), for surfaces that do not
/// cross: every pair of triangles whose boxes come within `enough` is
/// measured exactly; every other pair is `enough` apart at least. Once two
/// triangles are found within `useless` (a gap the caller cannot use), 0.
double surface_gap_lower_bound(const std::vector<std::array<Vec3, 3>>& a,
                               const std::vector<std::array<Vec3, 3>>& b, const TriangleTree& tree,
                               double enough, double useless = 0.0);

}  // namespace pd
