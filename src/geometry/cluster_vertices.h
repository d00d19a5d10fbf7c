// Simplifying a triangle mesh by vertex clustering.
#pragma once

#include "geometry/mesh.h"

namespace pd {

/// Vertex clustering: vertices snapped to a grid of `cells` cells along the
/// longest box side, merged per cell (their mean), collapsed and repeated
/// triangles dropped. Keeps the shape's outline at the grid's resolution.
Mesh cluster_vertices(const Mesh& mesh, int cells);

}  // namespace pd
