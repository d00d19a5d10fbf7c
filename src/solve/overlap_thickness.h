// The overlap thickness of two solids, with a certified bracket (issue 24).
//
// With sd_X the signed distance to solid X (positive inside), φ(x) =
// min(sd_A(x), sd_B(x)) is positive exactly inside A ∩ B and 1-Lipschitz;
// h = max φ is the radius of the largest ball inside the overlap. Any
// translation that separates the parts moves that ball's two copies apart, so
// it is at least 2h long: the thickness T = 2h is a lower bound of the
// penetration depth that does not depend on any decomposition. A tessellation
// sliver is thin (T small), a genuine clash thick.
//
// Branch and bound over boxes of the region where both parts' boxes meet, in
// the frame of the smaller part's largest flat areas (geometry/face_axes.h), so
// that a seated face or a pin's facets run along the boxes' sides: a
// box's φ is at most φ(centre) + its half-diagonal, and at most what the planes
// of both surfaces near it allow (geometry/solid_distance.h, solve/
// max_min_affine.h), which keeps large thin contacts cheap; the best φ found
// (cell centres, then a local ascent from each new best) is a lower bound.
// docs/solver.md says why each bound is sound.
#pragma once

#include <optional>

#include "geometry/solid_distance.h"
#include "geometry/types.h"
#include "tolerances.h"

namespace pd {

struct ThicknessLimits {
  long max_evaluations = tol::kThicknessMaxEvaluations;
  double seconds = tol::kThicknessSeconds;
  /// Replaces thickness_resolution(a, b) (float32 steps) where the parts'
  /// coordinates are finer (B-rep meshes, in doubles) and the caller asks no
  /// finer: a thin bracket is narrowed to it and no further.
  std::optional<double> resolution;
};

struct ThicknessResult {
  enum class Outcome {
    /// upper ≤ threshold: thin or no overlap. The search has then narrowed the
    /// bracket until lower > resolution (an overlap found) or upper ≤
    /// resolution (touching, as far as the coordinates tell), unless its
    /// budget ran out first.
    kBelow,
    kAbove,     ///< lower > threshold: a thick overlap
    kBudget,    ///< the evaluation budget ran out with the bracket straddling it
    kTime,      ///< the time box ran out likewise
    kNoInside,  ///< a part is not a closed solid: no thickness at all
  };
  Outcome outcome = Outcome::kBudget;
  double lower = 0.0;      ///< certified: T ≥ lower (0 when no common interior point was found)
  double upper = 0.0;      ///< certified: T ≤ upper
  Vec3 at = Vec3::Zero();  ///< centre of the thickest ball found (the lower bound's witness)
  /// Unit: from `at` towards a's nearest surface point; moving b that way
  /// thins the overlap there (a local escape, not a separating move).
  Vec3 direction = Vec3::UnitZ();
  /// The thickness the parts' coordinates resolve (thickness_resolution): an
  /// upper bound at or below it is touching.
  double resolution = 0.0;
  long evaluations = 0;  ///< distance evaluations (each of one part at one point)
  long cells = 0;        ///< boxes bounded
};

/// The thickness below which an overlap of a and b cannot be told from the
/// rounding of their coordinates: tol::kContactSteps float32 steps at each
/// part's largest coordinate.
double thickness_resolution(const SolidDistance& a, const SolidDistance& b);

/// The thickness T = 2h of a ∩ b, decided against `threshold` (the tolerance)
/// and against thickness_resolution(a, b): an interference has lower >
/// max(threshold, resolution); otherwise the bracket narrows until it shows an
/// overlap above the resolution or its upper end is at the resolution, so that
/// whether a thin pair touches does not depend on the threshold.
/// `upper_hint` is a known upper bound of T (the hulls' penetration depth: T is a
/// lower bound of the parts' depth, which the hulls' bounds from above).
ThicknessResult overlap_thickness(const SolidDistance& a, const SolidDistance& b, double threshold,
                                  double upper_hint = INFINITY, const ThicknessLimits& limits = {});

}  // namespace pd
