// `tolerance: auto`: each pair's own band, from its parts' tessellation sags
// and coordinate steps where they meet (docs/numerics.md, "Tessellation sag").
#pragma once

#include <functional>
#include <string>

#include "scene/parts.h"
#include "scene/scene.h"

namespace pd {

/// The gap artefacts two tessellated parts can show where they are closest: a
/// measured gap up to `value` may be a contact (docs/numerics.md, "Clearance").
struct GapBand {
  double value = 0.0;  ///< (s⁻_A + s⁻_B + steps)·(1 + kAutoToleranceMargin), not clamped
  std::string basis;   ///< the convex features, one clause per part
};

/// The tolerance a pair is decided against and what it rests on.
struct PairTolerance {
  double value = 0.0;
  std::string source;  ///< "declared" (a part's `sag`) or "measured"
  std::string basis;   ///< the features it rests on, one clause per part
  /// Under auto, set by pair_tolerance: the band at a point where the parts meet
  /// and the gap band there (contact_tolerance, gap_band, with the same parts and
  /// settings, `reach` around the point). Unset for a rule's tolerance.
  std::function<PairTolerance(const Vec3& at, double reach)> at_contact;
  std::function<GapBand(const Vec3& at, double reach)> gap_at;
  double pair_size = 0.0;  ///< the pair's rounding scale (pair_size), for deciding again
};

/// Where a and b can meet: the intersection of their boxes (a box spanning
/// the gap when they are apart, for clearance pairs).
Aabb meeting_region(const Part& a, const Part& b);

/// A length as the bands' texts write it (three significant digits).
std::string band_number(double x);

/// The band of a pair: AutoTolerance::band of each part's concave sag near
/// meeting_region (its declared `sag` instead when given) and coordinate
/// step. Both parts carry their sag (build_parts under auto). `units` names the
/// scene unit in the basis text. An upper band of contact_tolerance anywhere the
/// parts meet: the solve decides against it before it knows where the depth is.
PairTolerance pair_tolerance(const Part& a, const Part& b, const AutoTolerance& t,
                             const std::string& units);

/// The band at the contact: as pair_tolerance, with each part's concave sag of
/// the surface within `reach` of `at` (sag_at) instead of near the boxes'
/// overlap. Source and clamps as pair_tolerance; `at_contact` is not set.
PairTolerance contact_tolerance(const Part& a, const Part& b, const AutoTolerance& t,
                                const std::string& units, const Vec3& at, double reach);

/// The gap band at `at`: the parts' convex sags within `reach` of it (a part's
/// declared `sag` instead: an exporter's chordal deviation bounds both signs)
/// plus both coordinate steps, times 1 + kAutoToleranceMargin.
GapBand gap_band(const Part& a, const Part& b, const std::string& units, const Vec3& at,
                 double reach);

}  // namespace pd
