// The nonconvex refinement (the paper's §V), after the hull stage: a pair whose
// hull depth exceeds the tolerance and that has a nonconvex part is decided on
// the parts themselves — the exact mesh test, then convex pieces.
//
// The hull depth is an upper bound of the parts' depth (the hulls contain the
// parts), so every pair it leaves at or below the tolerance is final. For the
// rest: meshes that do not meet are separated ("mesh-test"); otherwise the
// nonconvex parts are decomposed (once per mesh file, cached, time-boxed, on
// threads in the parent) and the piece pairs are solved in the worker pool with
// the pair's method; the deepest vertex of one part inside the other is a lower
// bound that thin pieces cannot collapse. docs/solver.md says what the depth
// then means.
#pragma once

#include <functional>
#include <vector>

#include "batch/pair_result.h"
#include "batch/pair_solve.h"
#include "batch/run.h"
#include "scene/parts.h"

namespace pd {

/// What the parent learns of a flagged pair from the surfaces alone.
struct MeshVerdict {
  bool intersect = true;      ///< the surfaces meet or one contains the other
  double vertex_depth = 0.0;  ///< the deepest-vertex lower bound of the depth
  Vec3 vertex_direction = Vec3::UnitZ();
};

/// Whether the hull stage's result `r` of parts a, b needs the refinement.
bool needs_refinement(const PairResult& r, const Part& a, const Part& b);

/// At the hull stage: marks a final result of a pair with a nonconvex part as
/// confirmed (the hull depth bounds the parts' depth from above).
void note_hull_stage(PairResult& r, const Part& a, const Part& b);

/// The refined result of a flagged pair from its hull-stage result, the mesh
/// verdict and (when the meshes meet, or a clearance is checked) the piece-pair
/// result; `complete` = every decomposition used finished within its time box.
/// Pure: the status rules of docs/solver.md in one place.
PairResult decide_refined(const PairResult& hull, const MeshVerdict& mesh, const PairResult* pieces,
                          bool complete, double tolerance, double pair_size);

/// Refines the flagged pairs of `results` in place (same order as `pairs`);
/// the parts used get their `decomposition`. Seconds spent go to `seconds`.
void refine_nonconvex_pairs(std::vector<Part>& parts, const std::vector<std::pair<int, int>>& pairs,
                            std::vector<PairResult>& results, const RunOptions& options,
                            const std::function<PairChecks(int, int)>& checks);

}  // namespace pd
