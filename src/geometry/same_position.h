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
/// own. One pass through an open-addressing table of column indices: O(n),
/// no node per point (a sort was a fifth of reading and hulling a fine part).
std::vector<int> first_at_same_position(const Points& p);

/// The columns of `p` that are their own first (first[i] == i), in order:
/// each position once, as qhull and the convexity estimate need it (an STL
/// file repeats every corner; each copy would be hulled or projected again).
Points distinct_positions(const Points& p, const std::vector<int>& first);

/// m with each position once: the columns of `p` that are their own first
/// (`first` of first_at_same_position), in order, and the triangles' corners
/// renumbered to them. The triangles keep their order and their corners'
/// order; a triangle whose corners meet stays (a needle, as it was).
Mesh welded(const Mesh& m, const std::vector<int>& first);

/// The edges of m (corners welded by position) used by an odd number of its
/// triangles: the boundary of an open surface (holes, gaps, a missing face).
/// 0 for a closed mesh and for one without triangles. Degenerate triangles'
/// edges count as any other's.
long boundary_edges(const Mesh& m);
/// The same, with m's vertices already welded (`first` of first_at_same_position).
long boundary_edges(const Mesh& m, const std::vector<int>& first);

}  // namespace pd
