// Exact local minima of the gap inside a cap of directions.
//
// Local minima of the gap on the sphere (overlapping pairs) lie at facet normals
// of the Minkowski difference D = P − Q, and the value there is the facet's
// offset. Inside a cap C only some vertices of P and Q can be extreme; the
// facets of the local difference P' − Q' whose normals lie in C are exactly the
// facets of D there, so the lowest of them is the minimum of the gap over C's
// local minima. Cheap when C is small: P' and Q' are a few vertices each.
#pragma once

#include <optional>

#include "geometry/types.h"

namespace pd {

struct FacetCandidate {
  Vec3 normal;    ///< unit
  double offset;  ///< the gap at `normal`
};

/// Indices of the points of x that can be extreme (largest x·u when top, else
/// smallest) for some u within angle `radius` (<= π/2) of v. A superset: each
/// kept point passes a necessary test against the points extreme at v and at
/// eight directions on the cap's rim.
std::vector<int> extreme_in_cap(const Points& x, const Vec3& v, double radius, bool top);

/// The same among the points `among` only, which must hold every point of x
/// extreme somewhere in the cap (a larger cap's result): O(|among|), not O(|x|).
std::vector<int> extreme_in_cap_among(const Points& x, const std::vector<int>& among, const Vec3& v,
                                      double radius, bool top);

/// The outcome of searching a cap: `searched` is false when the local
/// difference would exceed `max_points` (nothing is known about the cap then);
/// `lowest` is empty when no facet normal lies in the cap.
struct CapSearch {
  bool searched = true;
  std::optional<FacetCandidate> lowest;
};

/// The lowest facet of P − Q whose normal lies within `radius` of v.
CapSearch lowest_facet_in_cap(const Points& p, const Points& q, const Vec3& v, double radius,
                              long max_points);

/// The lowest facet with its normal within `radius` of v of the local difference
/// P' − Q' (P' = p's columns pi, Q' = q's columns qj). When pi and qj hold every
/// vertex extreme in that cap, these are exactly P − Q's facets there.
std::optional<FacetCandidate> lowest_local_facet(const Points& p, const Points& q,
                                                 const std::vector<int>& pi,
                                                 const std::vector<int>& qj, const Vec3& v,
                                                 double radius);

}  // namespace pd
