// A certified bracket on the depth from GJK + EPA (the expanding polytope
// algorithm of van den Bergen) on the Minkowski difference D = P − Q, in the
// pair's unit frame.
//
// The depth is min over unit v of gap(v) = h_D(v). Two bounds come out of EPA:
// - upper: every unit v gives gap(v) >= depth (a translation of that length
//   along v separates the pair), so the lowest gap over EPA's face normals is an
//   upper bound;
// - lower: EPA's polytope is a closed triangle surface with vertices in D
//   around the origin, so the ball of radius (distance from the origin to the
//   surface) lies in D and depth >= that distance. For any unit n the distance
//   to a triangle is at least min over its vertices of n·x, so each face's bound
//   needs only dot products, whatever the rounding of its normal; the rounding
//   of the dots and of the differences is kEpaRounding (src/tolerances.h). The
//   bound does not need the polytope to be convex: only the origin must stay
//   enclosed, and it does while every face has it strictly on its inner side and
//   every face removed has the new vertex strictly outside (the cone replacing
//   them never sweeps over the origin). Each step checks both; a step that
//   cannot keep them ends the expansion with the bracket so far.
// When the nearest face's plane supports D (its gap equals its offset) the two
// meet: the bracket is closed and its direction is a facet normal of D.
#pragma once

#include "solve/objective.h"

namespace pd {

struct DepthBracket {
  /// depth >= lower (-inf when none is known: GJK undecided or a failed start).
  double lower = -std::numeric_limits<double>::infinity();
  /// depth <= upper = gap(direction), the lowest gap evaluated.
  double upper = std::numeric_limits<double>::infinity();
  Vec3 direction = Vec3::UnitZ();
  bool separated = false;  ///< upper <= 0: the hulls are apart or touch (depth 0)
  int iterations = 0;      ///< EPA expansions

  /// The bracket is closed to rounding: upper is the depth within kEpaBracket.
  bool certified() const;
};

/// GJK, then EPA from its tetrahedron for at most `max_iterations` expansions.
DepthBracket epa_bracket(const PairProblem& pr, int max_iterations);

}  // namespace pd
