// The depth of a closed EPA bracket recomputed exactly from the input
// coordinates (issue 29). A bracket closes to kEpaBracket in the unit frame,
// and the unit frame itself rounds the input (centring and scaling); at depths
// of 1e-9 of the pair's size both are a sizeable fraction of the depth. The
// exact step takes the polytope's faces near its nearest one, each as three
// differences a_i − b_j of the input doubles, and in exact rational arithmetic
// (GMP):
// - every such face has the origin strictly inside its plane, and the nearest
//   of those planes is at distance d (compared as exact squared distances);
// - that plane supports P − Q: the largest a·N minus the smallest b·N is its
//   offset exactly (a double pass keeps the few vertices within a generous
//   rounding band of the extremes, and only those are evaluated exactly).
// Then d is the depth: P − Q has a facet on that plane (three of its points
// span it and it supports P − Q), so depth <= d; and the polytope's surface
// winds around the origin with every face at least d away (the faces beyond
// the band are farther than the nearest by more than every rounding of their
// double bounds, epa.h), so depth >= d. The result is d rounded once (one
// square root of the nearest rational).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "solve/objective.h"

namespace pd {

struct ExactFacet {
  double depth = 0.0;              ///< in the input's units, relative error < 1e-15
  Vec3 direction = Vec3::UnitZ();  ///< the facet's outward unit normal (rounded)
};

/// a, b: the parts' input coordinates; faces: a certified bracket's near_faces
/// (solve/epa.h); bound: the largest distance (input units) the faces beyond
/// the band are known to exceed. Empty when the faces do not prove the depth
/// exactly (a face through or behind the origin, or the nearest plane not
/// supporting P − Q exactly: a facet of P − Q flat only to rounding, triangulated
/// across a reflex edge); the double bracket stands then.
std::optional<ExactFacet> exact_facet_depth(const Points& a, const Points& b,
                                            const std::vector<std::array<MinkowskiIndex, 3>>& faces,
                                            double bound);

}  // namespace pd
