// The axes of a part's largest flat areas, a frame its contacts line up with:
// the normal of the largest area facing one way, then the normal of the
// largest one nearly square to it, then their cross product. A washer's first
// axis is its normal, a block's are its edges, a pin's run along its facets
// and its axis. The overlap thickness splits space in the smaller part's frame
// (solve/overlap_thickness.h): a seated face is then a slab of boxes, not a
// staircase across axis-aligned ones.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "geometry/mesh_intersect.h"

namespace pd {

/// A rotation (orthonormal columns, determinant +1). Faces are grouped by
/// their normal rounded to about 0.06°; the second axis is the largest group
/// within 12° of square to the first, else any direction square to it. The
/// identity when the mesh has no face of positive area.
Eigen::Matrix3d face_axes(const PreparedMesh& mesh);

}  // namespace pd
