// A certified bracket on the depth from GJK + EPA (the expanding polytope
// algorithm of van den Bergen) on the Minkowski difference D = P − Q, in the
// pair's unit frame.
//
// The depth is min over unit v of gap(v) = h_D(v). Two bounds come out of EPA:
// - upper: every unit v gives gap(v) >= depth (a translation of that length
//   along v separates the pair), so the lowest gap over EPA's face normals is an
//   upper bound;
// - lower: EPA's polytope is a closed, consistently oriented triangle surface
//   with vertices in D. When every face has the origin on its inner side (each
//   seen from the origin at a positive solid angle) the surface winds around
//   the origin at least once, so the ball of radius (distance from the origin
//   to the surface) lies in the hull of its vertices, inside D, and depth >=
//   that distance. For any unit n the distance to a triangle is at least min
//   over its vertices of n·x, so each face's bound needs only dot products,
//   whatever the rounding of its normal; the rounding of the dots and of the
//   differences is kEpaRounding (src/tolerances.h), and "inside" means inside by
//   more than it. The argument needs neither convexity nor how the surface was
//   reached: a bound is taken whenever the nearest face (so every face) has the
//   origin inside. GJK's tetrahedron may have the origin on a face or an edge
//   (symmetric pairs); the expansion lifts the nearest face first, and the
//   bound starts once no face is left through the origin.
// When the nearest face's plane supports D (its gap equals its offset) the two
// meet: the bracket is closed and its direction is a facet normal of D.
// Touching pairs: GJK's simplex through the origin yields a supporting plane of
// D through it (solve/gjk.h), so the upper end is about 0 and the pair is
// settled without EPA.
#pragma once

#include <array>
#include <vector>

#include "solve/objective.h"

namespace pd {

inline constexpr std::size_t kMaxNearFaces = 64;

struct DepthBracket {
  /// depth >= lower: EPA's bound, else GJK's −|x| (the signed minimum of the gap
  /// is at least minus the distance to any point x of D); -inf when none is known.
  double lower = -std::numeric_limits<double>::infinity();
  /// depth <= upper = gap(direction), the lowest gap evaluated.
  double upper = std::numeric_limits<double>::infinity();
  Vec3 direction = Vec3::UnitZ();
  bool separated = false;  ///< upper <= 0: the hulls are apart or touch (depth 0)
  int iterations = 0;      ///< EPA expansions

  /// A certified bracket whose upper end is below kExactFacetDepth: the
  /// polytope's faces (vertex indices, counter-clockwise seen from outside)
  /// whose bound is within 4·kEpaRounding of the nearest face's bound
  /// `nearest_low`; every other face is farther than the depth, exactly too.
  /// solve/exact_facet.h recomputes the depth from them exactly. Empty
  /// otherwise, or when more than kMaxNearFaces faces are that near.
  std::vector<std::array<MinkowskiIndex, 3>> near_faces;
  double nearest_low = 0.0;
  /// With near_faces: every vertex of the polytope (solve/exact_hull_depth.h).
  std::vector<MinkowskiIndex> vertices;

  /// The bracket is closed to rounding: upper is the depth within kEpaBracket.
  bool certified() const;
};

/// GJK, then EPA from its tetrahedron for at most `max_iterations` expansions.
DepthBracket epa_bracket(const PairProblem& pr, int max_iterations);

}  // namespace pd
