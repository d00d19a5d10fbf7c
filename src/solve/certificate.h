// A certificate that MLSL's best direction is the global minimum of the gap.
//
// For any point x of D = P − Q, gap(u) = h_D(u) >= x·u. The support point
// x_c = p*(c) − q*(c) found while evaluating the gap at a direction c therefore
// bounds the gap from below on a whole cell of the cube-sphere grid. A cell is a
// spherical quadrilateral with great-circle edges, and along a great-circle arc
// shorter than π a linear function positive at both ends has its minimum at an
// end; so min over the cell of x·u is the smallest of x·corner when those are
// all positive — a bound without any Lipschitz slack.
// A cell whose bound (from its own support point or a neighbour's) exceeds the
// best gap known cannot hold the global minimum. The cells left open are
// covered by a few caps, and each cap is searched exactly for its lowest facet
// (solve/neighbourhood.h). No lower facet anywhere: the best gap is the global
// minimum, to rounding. MLSL's sampling stays the search; this only proves it.
#pragma once

#include <array>
#include <vector>

#include "solve/objective.h"

namespace pd {

/// A cell of the cube-sphere grid: its centre and the largest angle from the
/// centre to a point of the cell.
struct SphereCell {
  Vec3 centre;
  double radius;
  std::array<Vec3, 4> corners;
  int face, i, j;
};

/// 6·n² cells: each face of the cube cut into n×n squares, projected.
const std::vector<SphereCell>& cube_sphere_cells(int n);

/// Caps (centre, angular radius) covering every cell where the gap may lie
/// below `best`: one per connected group of open cells. `ok` is false when the
/// open region needs more than `max_caps` caps of radius <= `max_radius`.
struct CapCover {
  bool ok = true;
  std::vector<std::pair<Vec3, double>> caps;
  long evaluations = 0;
};
CapCover open_region_caps(const PairProblem& pr, double best, int grid, double max_radius,
                          int max_caps);

/// The support points and gaps at the cell centres of a grid: they do not depend
/// on `best`, so a certificate's rounds share them.
struct CellSupports {
  std::vector<Vec3> x;
  std::vector<double> g;
};
CellSupports cell_supports(const PairProblem& pr, int grid);
/// open_region_caps on supports already computed (`evaluations` is then 0).
CapCover open_region_caps(const CellSupports& s, double best, int grid, double max_radius,
                          int max_caps);

}  // namespace pd
