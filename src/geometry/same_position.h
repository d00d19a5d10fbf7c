// Welding by position: which columns of a point set are the same point. STL
// stores each triangle's corners, and multi-body exports repeat the corners
// where bodies meet, so every test of shells, edges or closedness welds first.
#pragma once

#include <vector>

#include "geometry/types.h"

namespace pd {

/// For each column of `p`, the first column (smallest index) with equal
/// coordinates (−0 equals 0). A column with a non-finite coordinate is its
/// own. A sort, not a map or hash: O(n log n) without a node per point, and
/// the same answer whatever the order of equal keys.
std::vector<int> first_at_same_position(const Points& p);

}  // namespace pd
