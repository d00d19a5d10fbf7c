// The nonconvex refinement, after the hull stage: a pair whose hull depth
// exceeds the tolerance and that has a nonconvex part is decided on the parts
// themselves, where they meet.
//
// The hull depth is an upper bound of the parts' depth (the hulls contain the
// parts), so every pair it leaves at or below the tolerance is final. For the
// rest: meshes that do not meet are separated ("mesh-test"); otherwise the
// overlap thickness (solve/overlap_thickness.h) decides with a certified
// bracket, and the deepest vertex of one part inside the other — a lower bound
// of any separating move — guards thin parts pushed deep into another. Pairs
// with a clearance check, parts in `pieces: decompose` and parts without a
// surface keep the paper's §V: convex pieces of a whole-part decomposition,
// solved in the worker pool. docs/solver.md says what each depth means.
#pragma once

#include <functional>
#include <vector>

#include "batch/pair_solve.h"
#include "batch/part_solids.h"
#include "batch/run.h"
#include "results/pair_result.h"
#include "scene/parts.h"
#include "solve/overlap_thickness.h"

namespace pd {

/// What the parent learns of a flagged pair from the surfaces alone.
struct MeshVerdict {
  bool intersect = true;      ///< the surfaces meet or one contains the other
  double vertex_depth = 0.0;  ///< the deepest-vertex lower bound of the depth
  Vec3 vertex_direction = Vec3::UnitZ();
  /// Where: the middle of the deepest vertex (or surface sample) and its
  /// nearest point on the other surface, when one lies inside.
  std::optional<Vec3> vertex_at;
};

/// Whether the hull stage's result `r` of parts a, b needs the refinement (a
/// duplicate, one mesh placed twice, does not: its parts overlap wholly).
bool needs_refinement(const PairResult& r, const Part& a, const Part& b);
/// The same, were the parts' convexity `convex_a` and `convex_b`.
bool needs_refinement(const PairResult& r, const Part& a, std::optional<bool> convex_a,
                      const Part& b, std::optional<bool> convex_b);

/// At the hull stage: marks a final result of a pair with a part that is or
/// may be nonconvex as confirmed (the hull depth bounds the parts' depth from
/// above, and is theirs for convex parts) or not (a moving pair's interference
/// with a nonconvex part rests on its hulls).
void note_hull_stage(PairResult& r, const Part& a, const Part& b);

/// The refined result of a flagged pair from its hull-stage result, the mesh
/// verdict and (when the meshes meet, or a clearance is checked) the piece-pair
/// result; `complete` = every decomposition used finished within its time box.
/// Pure: the status rules of docs/solver.md in one place.
PairResult decide_refined(const PairResult& hull, const MeshVerdict& mesh, const PairResult* pieces,
                          bool complete, double tolerance, double pair_size);

/// The refined result of a flagged pair whose surfaces meet, from its hull-stage
/// result, the mesh verdict (its vertex_depth: the deepest point of either
/// surface inside the other, geometry/solid_distance.h) and the overlap thickness. Pure: the status
/// rules of docs/solver.md ("Overlap thickness") in one place. `why_not` is the parts' note when a
/// part is no closed solid.
PairResult decide_thickness(const PairResult& hull, const MeshVerdict& mesh,
                            const ThicknessResult& t, double tolerance, double pair_size,
                            const std::string& why_not);

/// Measures the on-demand convexities the pairs turn on (batch/convexity_on_demand.h)
/// and refines the pairs that then need it, in place in `results` (same order
/// as `pairs`); the parts measured get their convexity, the parts used their
/// `decomposition`.
void refine_nonconvex_pairs(std::vector<Part>& parts, const std::vector<std::pair<int, int>>& pairs,
                            std::vector<PairResult>& results, const RunOptions& options,
                            const std::function<PairChecks(int, int)>& checks);
/// The same, each part's distances from `solids`: a part's are built once
/// for its convexity measure and its pairs while the budget holds them, and
/// let go after its last pair.
void refine_nonconvex_pairs(std::vector<Part>& parts, const std::vector<std::pair<int, int>>& pairs,
                            std::vector<PairResult>& results, const RunOptions& options,
                            const std::function<PairChecks(int, int)>& checks, PartSolids& solids);

}  // namespace pd
