// The axes of a part's largest flat areas, a frame its contacts line up with:
// the normal of the largest area facing one way, then the normal of the
// largest one nearly square to it, then their cross product. A washer's first
// axis is its normal, a block's are its edges, a pin's run along its facets
// and its axis. The overlap thickness splits space in the smaller part's frame
// (solve/overlap_thickness.h): a seated face is then a slab of boxes, not a
// staircase across axis-aligned ones.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "geometry/types.h"

namespace pd {

/// A rotation (orthonormal columns, determinant +1). Faces are grouped by
/// their normal rounded to about 0.06°; the second axis is the largest group
/// within 12° of square to the first, else any direction square to it. The
/// identity when no triangle has a positive area. A part's are kept by its
/// TriangleTree (PreparedMesh::face_axes), whose boxes are taken in them.
Eigen::Matrix3d face_axes(const std::vector<std::array<Vec3, 3>>& triangles);
/// The same of `count` triangles from `triangles` on.
Eigen::Matrix3d face_axes(const std::array<Vec3, 3>* triangles, size_t count);

}  // namespace pd
