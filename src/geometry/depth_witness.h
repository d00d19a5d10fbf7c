// Where a convex pair's depth (or gap) is: one point to show a reviewer and to
// centre a view on. docs/solver.md, "Where: the witness point".
#pragma once

#include "geometry/types.h"

namespace pd {

/// The witness of a convex pair's depth along the unit direction d, in the
/// DepthSolution convention (solve/result.h: moving b along +d separates the
/// pair; when apart, d is a separating normal pointing from a to b). a and b are
/// the two convex sets' points (hull vertices will do), in any frame; the result
/// is in the same frame.
///
/// F_a is the face of conv(a) supporting +d (its points within
/// tol::kWitnessFace of the pair's size of the plane), F_b the face of conv(b)
/// supporting −d. Moving b by the depth along d makes them touch on the patch
/// F_a ∩ (F_b + depth·d); its centroid c (the area centroid of the two faces'
/// projections' intersection across d; a segment's or point's middle when the
/// patch is one) lies in F_a's plane. The witness is c moved along −d to the
/// middle of the slab between the two support planes, max d·a and min d·b: the
/// midpoint of the two points that meet when b moves out. When the pair
/// overlaps it is clamped to the intersection of the two sets' boxes (one part
/// thinner along d than the depth, as a pin inside a block's hull: the middle
/// of the slab would lie outside it); when apart it is the middle of the gap.
/// Cost: one pass over each set and a 2-D clip of the two faces. Finite for
/// finite input; d need not be the optimal direction (the patch is then the
/// faces' nearest region, and the witness still lies between them).
Vec3 depth_witness(const Points& a, const Points& b, const Vec3& d);

}  // namespace pd
