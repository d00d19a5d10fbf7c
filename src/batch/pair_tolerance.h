// `tolerance: auto`: each pair's own band, from its parts' tessellation sags
// and coordinate steps where they meet (docs/numerics.md, "Tessellation sag").
#pragma once

#include <string>

#include "scene/parts.h"
#include "scene/scene.h"

namespace pd {

/// The tolerance a pair is decided against and what it rests on.
struct PairTolerance {
  double value = 0.0;
  std::string source;  ///< "declared" (a part's `sag`) or "measured"
  std::string basis;   ///< the features it rests on, one clause per part
};

/// Where a and b can meet: the intersection of their boxes (a box spanning
/// the gap when they are apart, for clearance pairs).
Aabb meeting_region(const Part& a, const Part& b);

/// The band of a pair: AutoTolerance::band of each part's concave sag near
/// meeting_region (its declared `sag` instead when given) and coordinate
/// step. Both parts carry their sag (build_parts under auto). `units` names the
/// scene unit in the basis text.
PairTolerance pair_tolerance(const Part& a, const Part& b, const AutoTolerance& t,
                             const std::string& units);

}  // namespace pd
