// The exact step's second way (solve/exact_facet.h declined): the depth from
// an exact hull of points of P − Q, grown until its nearest facet supports
// P − Q. V starts as EPA's polytope vertices, each a difference a_i − b_j of
// the input doubles, exact in CGAL's exact kernel (Epeck). hull(V) lies in
// P − Q, so when it holds the origin strictly inside, its nearest facet's
// distance is a lower bound of the depth; when that facet's plane supports
// P − Q exactly (the largest a·N minus the smallest b·N is its offset) it is a
// facet of P − Q too and the bound is the depth. Otherwise the exact support
// point in its normal joins V and the hull is built again: each round adds a
// vertex of P − Q, so the rounds end; a bounded number are tried. A facet of
// P − Q flat only to rounding (a rotated cube's face, its four corners not
// exactly coplanar) is what needs it: EPA may have triangulated it across an
// edge reflex in exact arithmetic. Cost: ~1 ms, paid by such pairs only.
#pragma once

#include <optional>
#include <vector>

#include "solve/epa.h"
#include "solve/exact_facet.h"

namespace pd {

/// a, b: input coordinates; vertices: EPA's polytope vertices (DepthBracket).
std::optional<ExactFacet> exact_hull_depth(const Points& a, const Points& b,
                                           const std::vector<MinkowskiIndex>& vertices);

/// The exact step of a closed bracket with near faces (solve/epa.h): the near
/// faces (exact_facet_depth), else the exact hull; `scale` is the pair frame's.
std::optional<ExactFacet> exact_bracket_depth(const Points& a, const Points& b,
                                              const DepthBracket& bracket, double scale);

}  // namespace pd
