// The exact search of a cap whose local Minkowski difference is too large for
// one hull (issue 12: two bumpy float32 faces resting on each other keep every
// rim vertex extreme for any tilt larger than the bumps, so a 0.1 rad cap of two
// 1000-vertex plates holds 500 × 500 differences).
//
// The cap is cut into cells with great-circle edges (squares of the gnomonic
// plane tangent at its centre). Each cell's centre support point x bounds the gap
// below on the cell (gap(u) >= x·u, smallest at a corner: solve/certificate.h);
// a cell whose bound exceeds the best gap is closed. An open cell is searched
// exactly (solve/neighbourhood.h) once its own local difference is small, else
// cut into four. Cells shrink towards the minimum, where the tilt falls below
// the bumps and the extreme vertices thin out. Candidate vertices are inherited
// from the parent cell, so a cell costs O(its candidates), not O(n + m).
#pragma once

#include <limits>

#include "solve/neighbourhood.h"

namespace pd {

/// Facets of P − Q with normals within `radius` (<= 0.5) of `centre` and below
/// `best`: `lowest` is the lowest found below `best` (empty when none is).
/// Cells are closed against the lowest gap of any cell centre too (`witness`,
/// `witness_gap`: that direction and its gap), so a facet of the cap lying above
/// a centre's gap may go unreported: it is then not the global minimum (the
/// witness is lower), and the certificate finds that in the cap that holds it.
/// The search stops as soon as a centre's gap is at or below `settle_at` (the
/// contact resolution: the pair is settled; `witness` is that centre).
/// `searched` is false when more than `max_cells` cells would be needed; then
/// nothing is known about the cap. Leaves hold <= `leaf_points` differences.
/// `cells` counts the cells examined (one support evaluation each, over the
/// cell's candidate vertices).
struct SubdividedSearch {
  CapSearch result;
  long cells = 0;
  Vec3 witness = Vec3::UnitZ();
  double witness_gap = 0;
};
SubdividedSearch lowest_facet_subdivided(
    const Points& p, const Points& q, const Vec3& centre, double radius, double best,
    long leaf_points, long max_cells, double settle_at = -std::numeric_limits<double>::infinity());

}  // namespace pd
