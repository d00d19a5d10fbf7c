// GJK (Gilbert, Johnson & Keerthi) on the Minkowski difference D = P − Q of a
// pair in its unit frame, as the first step of the EPA bracket (solve/epa.h).
//
// It answers one question: does D hold the origin? Either a direction with
// gap <= 0 is found (D lies in a closed half-space without the origin inside:
// the hulls are apart or touch, depth 0 proved), or a tetrahedron of support
// points of D that encloses the origin (EPA's starting polytope). Near a
// contact the origin lies on D's boundary to rounding and neither may come: the
// search then stops undecided after a bounded number of support evaluations,
// and the caller's MLSL decides the pair as before.
#pragma once

#include <array>

#include "solve/objective.h"

namespace pd {

struct GjkResult {
  enum class Outcome { kSeparated, kEnclosed, kUndecided };
  Outcome outcome = Outcome::kUndecided;
  Vec3 direction = Vec3::UnitZ();   ///< unit; the lowest gap seen (<= 0 when kSeparated)
  double gap = 0.0;                 ///< gap(direction), as PairProblem::gap computes it
  std::array<Vec3, 4> tetrahedron;  ///< kEnclosed: support points of D around the origin
};

/// At most `max_iterations` support evaluations.
GjkResult gjk_enclose_origin(const PairProblem& pr, int max_iterations);

}  // namespace pd
