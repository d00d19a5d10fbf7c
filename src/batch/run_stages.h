// The stages of run_scene (batch/run.h), each a function of its own: the
// candidate pairs (the broad phase, the scene's listed pairs, or a shard's),
// the reuse of an earlier report's results and the solves in worker processes.
// The refinement of nonconvex pairs is batch/refine.h.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "batch/pair_solve.h"
#include "batch/run.h"

namespace pd {

/// The pairs a run checks, and what became of the others.
struct CandidatePairs {
  std::vector<std::pair<int, int>> pairs;  ///< part indices, a < b, sorted
  long all_pairs = 0;  ///< n(n − 1)/2, the listed pairs, or a shard's planned pairs
  long culled = 0;     ///< removed by the broad phase
  long unchecked = 0;  ///< never formed: a part of theirs is unusable
};

/// Every pair of usable parts whose culling boxes touch within the broad
/// phase's reach (batch/broad_phase.h). A part that failed to load is reported
/// with its reason in the part list; its pairs cannot be formed (unchecked).
CandidatePairs broad_phase_pairs(const std::vector<Part>& parts, const Checks& checks);

/// The scene's listed pairs (part ids) as part indices, sorted, each once.
CandidatePairs listed_pairs(const std::vector<Part>& parts,
                            const std::vector<std::pair<std::string, std::string>>& listed);

/// Shard `shard`'s planned pairs, kept when their culling boxes touch: exactly
/// the unsharded broad phase's decision (boxes_touch), pair by pair; and the
/// shard's manifest. `loaded`: the scene index of each of `parts`;
/// `scene_parts`: how many parts the scene has.
CandidatePairs shard_pairs(const ScenePlan& plan, const ShardSpec& shard,
                           const std::vector<int>& loaded, const std::vector<Part>& parts,
                           const Checks& checks, long scene_parts, ShardManifest& manifest);

/// The checks of the pair of parts (a, b): its clearance (the scene's minimum,
/// or the pair's own) and the motion when either part moves.
/// `auto_tolerance`: each pair also gets its own band (batch/pair_tolerance.h);
/// `units` names the scene unit in its basis.
std::function<PairChecks(int, int)> pair_checks_of(
    const std::vector<Part>& parts, const Checks& checks,
    const std::optional<AutoTolerance>& auto_tolerance = std::nullopt,
    const std::string& units = "mm");

/// --reuse (options.reuse): each pair whose old result stands (batch/reuse.h;
/// pairs of nonconvex parts too, whose old result is the refined one and is
/// not refined again; never one whose tolerance or clearance, e.g. from rules,
/// is not the one it was decided against, as `checks` gives them now) gets it
/// in `results` (one per pair), reported to options.on_pair. Returns the
/// indices of the other pairs, in order: those still to solve. `counts`, when
/// given, gets how many were reused and why the others were not.
std::vector<size_t> reuse_results(const std::vector<Part>& parts,
                                  const std::vector<std::pair<int, int>>& pairs,
                                  const std::vector<std::string>& part_hashes,
                                  const std::string& settings_hash, const RunOptions& options,
                                  std::vector<PairResult>& results,
                                  const std::function<PairChecks(int, int)>& checks = {},
                                  ReuseCounts* counts = nullptr);

/// Solves the pairs `to_solve` (indices into `pairs`) in worker processes into
/// `results`, largest first (by the work of one support evaluation: no worker
/// idles at the end on a long tail). A pair the refinement takes on is
/// reported to options.on_pair when it is decided, not here.
void solve_pairs(const std::vector<Part>& parts, const std::vector<std::pair<int, int>>& pairs,
                 std::vector<size_t> to_solve, const RunOptions& options,
                 const std::function<PairChecks(int, int)>& checks,
                 std::vector<PairResult>& results);

}  // namespace pd
