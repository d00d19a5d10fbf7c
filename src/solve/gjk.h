// GJK (Gilbert, Johnson & Keerthi) on the Minkowski difference D = P − Q of a
// pair in its unit frame, as the first step of the EPA bracket (solve/epa.h).
//
// It answers one question: does D hold the origin? Either a direction with
// gap <= 0 is found (D lies in a closed half-space without the origin inside:
// the hulls are apart or touch, depth 0 proved), or a tetrahedron of support
// points of D that holds the origin (EPA's starting polytope; the origin may lie
// on one of its faces or edges, to rounding: symmetric pairs put it there).
//
// When the origin lies on the simplex to rounding (a segment or triangle of
// support points through it), GJK's direction towards the origin is undefined;
// the simplex is then completed by support points off its span. A side with no
// support point beyond the simplex is a supporting plane of D through the
// origin: the pair touches, and that plane's gap (about 0) is the result's
// `gap`. Otherwise the search stops undecided after a bounded number of support
// evaluations or when it stops getting closer to the origin, and the caller's
// MLSL decides the pair as before.
#pragma once

#include <array>
#include <limits>

#include "solve/objective.h"

namespace pd {

struct GjkResult {
  enum class Outcome { kSeparated, kEnclosed, kUndecided };
  Outcome outcome = Outcome::kUndecided;
  Vec3 direction = Vec3::UnitZ();  ///< unit; the lowest gap seen (<= 0 when kSeparated)
  double gap = 0.0;                ///< gap(direction), as PairProblem::gap computes it
  /// The signed minimum of the gap is at least this: −|x| − kEpaRounding for the
  /// simplex point x nearest the origin (x lies in D, and gap(v) >= v·x for any
  /// unit v). −inf before the first simplex.
  double lower = -std::numeric_limits<double>::infinity();
  std::array<Vec3, 4> tetrahedron;  ///< kEnclosed: support points of D around the origin
  std::array<MinkowskiIndex, 4> tetrahedron_ids;  ///< their vertex indices
};

/// At most `max_iterations` support evaluations.
GjkResult gjk_enclose_origin(const PairProblem& pr, int max_iterations);

}  // namespace pd
