// Welding by position: which columns of a point set are the same point. STL
// stores each triangle's corners, and multi-body exports repeat the corners
// where bodies meet, so every test of shells, edges or closedness welds first.
#pragma once

#include <vector>

#include "geometry/mesh.h"
#include "geometry/types.h"

namespace pd {

/// For each column of `p`, the first column (smallest index) with equal
/// coordinates (−0 equals 0). A column with a non-finite coordinate is its
/// own. A sort, not a map or hash: O(n log n) without a node per point, and
/// the same answer whatever the order of equal keys.
std::vector<int> first_at_same_position(const Points& p);

/// The edges of m (corners welded by position) used by an odd number of its
/// triangles: the boundary of an open surface (holes, gaps, a missing face).
/// 0 for a closed mesh and for one without triangles. Degenerate triangles'
/// edges count as any other's.
long boundary_edges(const Mesh& m);

}  // namespace pd
