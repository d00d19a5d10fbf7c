// The truly exact penetration depth of two point sets' hulls, for the tests and
// the benchmark (issue 29): the hull of the Minkowski difference M = {a_i − b_j}
// of the input doubles, built with exact predicates and exact constructions
// (CGAL's Epeck: the differences are exact rationals, not rounded doubles), and
// the depth min over its facets of the facet plane's distance from the origin,
// compared as exact squared distances and rounded once at the end (one square
// root of the nearest rational, relative error below 1e-15).
//
// solve/exact.h's reference (qhull on the unit frame's rounded differences) is
// exact to kGapRounding of the pair's scale; at depths of 1e-9 of the scale and
// below that rounding is a visible fraction of the depth, and this one is the
// truth there.
#pragma once

#include <cstddef>

#include "geometry/types.h"

namespace pd::testgen {

struct ExactReference {
  /// > 0 when the origin is strictly inside M (the hulls interpenetrate); 0
  /// when they touch or are apart (M flat, or the origin on or outside it).
  double depth = 0.0;
  Vec3 direction = Vec3::UnitZ();  ///< the nearest facet's outward unit normal
  /// Every difference went into the exact hull. False above kExactReferencePoints
  /// differences: then only the differences qhull keeps as vertices of M (in
  /// double precision, on the world coordinates) do, a hull that can miss a
  /// vertex lying within qhull's rounding (~1e-15 of the pair's size) of it.
  bool all_points = true;
};

/// Beyond this many differences the exact hull gets qhull's vertices only.
inline constexpr std::size_t kExactReferencePoints = 40000;

/// a, b: the two parts' points in world coordinates (any scale).
ExactReference exact_reference_depth(const Points& a, const Points& b);

}  // namespace pd::testgen
