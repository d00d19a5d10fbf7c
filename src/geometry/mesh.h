// A triangle mesh: the surface of a part as read (before any hull).
#pragma once

#include <Eigen/Core>

#include "geometry/types.h"

namespace pd {

/// Triangles index `vertices` (one column per triangle, counter-clockwise seen
/// from outside when the file is oriented). A point cloud has no triangles.
using Triangles = Eigen::Matrix<int, 3, Eigen::Dynamic>;

struct Mesh {
  Points vertices;
  Triangles triangles;
};

}  // namespace pd
