// Tolerance auto at the contact: a pair is first decided against the band of
// every feature where its parts' boxes meet (an upper band: the solve needs a
// threshold before it knows where the depth is), then, once its depth and the
// point `at` where it was found are known, against the band of the features
// there (docs/numerics.md, "The band at the contact").
#pragma once

#include <functional>
#include <optional>

#include "batch/pair_tolerance.h"
#include "geometry/solid_distance.h"
#include "results/pair_result.h"
#include "solve/overlap_thickness.h"

namespace pd {

/// How far from the point `at` a depth's surfaces can be: the centre of the
/// thickest overlap is within half the depth of both surfaces; `upper` (the
/// depth's upper bound) plus the band the pair was decided against leaves room
/// for the facets' own deviation.
inline double contact_reach(double upper, double band) {
  return upper + band;
}

/// The status of depth bounds [lower, upper] against the band `t` (classify's
/// rounding slack `slack`): interference when lower > t, a false positive when
/// upper ≤ t, undecided otherwise (separated is classify's, not decided here).
Status status_against(double lower, double upper, double t, double slack);

/// Decides `r` again against the band at its `at`, when `wide` (the band it was
/// decided against) can say it there (`at_contact`) and `r`'s depth and `at` are
/// of the parts themselves (depth_source thickness or surface: the thickest
/// overlap, the deepest surface point). Only a false positive, an interference
/// or an undecided pair is decided again, from its depth bounds: the band at the
/// contact replaces the wide one when it decides them; when it does not (the
/// bracket straddles it), the wide band's decision stands and the basis says
/// so. Its result does not depend on `r`'s earlier band: deciding twice is
/// deciding once (the refinement cache and --reuse store decided results).
void decide_at_contact(PairResult& r, const PairTolerance& wide);

/// Under auto (`band` with `gap_at`), a separated pair checked for clearance:
/// records in `r` the gap band of the convex sags within contact_reach of the
/// middle of its gap `at` (the whole parts' worst when no place is known), and
/// the features it rests on (gap_band, gap_basis). Nothing otherwise.
void note_gap_band(PairResult& r, const PairTolerance* band, const std::optional<Vec3>& at);

/// overlap_thickness decided against the band at its thickest point: first
/// against `tolerance` (the wide band); when that says "below" and `band`
/// (under auto) gives a narrower band at the point found that the bracket
/// straddles, once more against that band, warm (the first upper bound as the
/// hint). The brackets are merged (the higher lower bound with its witness, the
/// lower upper bound) and the outcome is said against `tolerance`, as
/// decide_thickness expects; decide_at_contact then says it at the contact.
/// `surface_at()` (the deepest surface point, found only when asked) is the
/// contact when the search finds no common interior point (a sliver thinner
/// than its cells).
ThicknessResult thickness_at_contact(const SolidDistance& a, const SolidDistance& b,
                                     double tolerance, const PairTolerance* band, double upper_hint,
                                     const std::function<std::optional<Vec3>()>& surface_at);

/// A bracket `t` (decided against `tolerance`) narrowed once more against a
/// lower `threshold`, warm (t's upper end as the hint), and merged: the higher
/// lower bound with its witness, the lower upper bound, the outcome said
/// against `tolerance` again, t's resolution kept (`limits` may search finer).
ThicknessResult thickness_again(const SolidDistance& a, const SolidDistance& b,
                                const ThicknessResult& t, double threshold, double tolerance,
                                const ThicknessLimits& limits = {});

}  // namespace pd
