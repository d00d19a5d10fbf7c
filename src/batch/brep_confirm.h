// B-rep pairs: each verdict of the mesh stage made sure of on the exact solids
// (docs/solver.md, "B-rep parts"). After the hull stage and the refinement,
// every pair of B-rep parts gets an `exact` check:
// 1. certified by the deflection bound, when both parts' sags are bounds: the
//    mesh stage's bracket of the depth, widened by twice the larger sag, holds
//    for the solids (a mesh within s of its solid moves every signed distance,
//    hence the overlap thickness's h and the penetration depth, by at most s
//    per part), and decides the pair if it still does so widened; a pair
//    apart by more than both sags (its hulls' or its meshes' gap) is apart,
//    and one the meshes found touching is within the tolerance when its
//    bracket is, widened (its status stays the meshes');
// 2. else confirmed on the solids in worker processes (brep/exact_pair.h):
//    their distance, and where they meet a bracket of the overlap thickness,
//    decided by the same rule as the mesh bracket, accepted when it agrees with
//    the widened mesh bracket.
// A pair with one part that is no B-rep gets `skipped`.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "batch/pair_solve.h"
#include "batch/run.h"
#include "brep/exact_pair.h"
#include "results/pair_result.h"
#include "scene/parts.h"

namespace pd {

/// The mesh stage's certified bracket of the pair's depth, scene units: its
/// `depth_bounds`, else [depth, depth] when the depth is the hulls' and both
/// parts are convex, else [0, depth] (a hull depth over a nonconvex part bounds
/// from above); [0, 0] for a separated pair.
std::array<double, 2> mesh_bracket(const PairResult& r, bool convex_pair);

/// What pure deciding needs of a pair: its tolerance, rounding scale, the
/// parts' larger sag and whether both sags are bounds.
struct ExactContext {
  double tolerance = 0.0;
  double pair_size = 0.0;
  double sag = 0.0;     ///< the larger of the two parts' sags (scene units)
  bool bounds = false;  ///< both sags are certified bounds
  std::optional<double> clearance;
};

/// How far the mesh bracket of a pair of B-rep parts widens for their solids:
/// twice the larger sag, when both sags are bounds (else none: nothing is
/// certified by the bound). The refinement narrows a thin overlap's bracket
/// until this widening still leaves it within the tolerance.
std::optional<double> bound_widening(const Part& a, const Part& b);

/// Step 1: the verdict the widened bracket certifies, if any (basis kBound).
/// A separated pair needs `hull_distance` (a lower bound of the meshes'
/// distance: the hulls' gap, or the meshes' own) beyond twice the sag.
std::optional<ExactCheck> certify_by_bound(const PairResult& r, const std::array<double, 2>& mesh,
                                           const ExactContext& c,
                                           std::optional<double> hull_distance = std::nullopt);

/// Step 1 for a pair the mesh stage found apart or touching (status
/// separated, no clearance checked) that no gap certified apart: its meshes
/// overlap by at most hi (`depth_bounds`' upper end where the surfaces meet,
/// else 0), so the solids by at most hi + 2s. Within the tolerance that is
/// certified (`false_positive` with `depth_bounds` [0, hi + 2s]: any overlap of
/// the solids is one); whether the solids touch, overlap that little or stand
/// apart, only they can say, and the status stays the meshes' (a contact's
/// status does not follow the tolerance).
std::optional<ExactCheck> certify_within_tolerance(const PairResult& r, const ExactContext& c);

/// Step 2's verdict from the solids' measurements, and the pair made to agree
/// with it: a decisive verdict that agrees with the widened mesh bracket sets
/// the status (touching and apart are `separated`), and where that changes the
/// status the depth is the solids' (`depth_source` "exact": the bracket's end
/// that decides, its lower end for an interference, its upper end otherwise).
/// Pure.
void decide_exact(PairResult& r, const std::array<double, 2>& mesh, const ExactContext& c,
                  const ExactMeasure& m);

/// Runs steps 1 and 2 over the pairs with a B-rep part (in options.jobs worker
/// processes, each pair within options.pair_timeout), reporting each to
/// options.on_pair when it is final (the earlier stages hold B-rep pairs back).
void confirm_brep_pairs(const std::vector<Part>& parts,
                        const std::vector<std::pair<int, int>>& pairs,
                        std::vector<PairResult>& results, const RunOptions& options,
                        const std::function<PairChecks(int, int)>& checks,
                        const std::string& units);

/// Whether a pair waits for confirm_brep_pairs before it is reported.
inline bool held_for_exact(const Part& a, const Part& b) {
  return a.brep.has_value() || b.brep.has_value();
}

}  // namespace pd
