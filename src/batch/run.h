// The pipeline: scene → parts → hulls → candidate pairs → solves → results.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "batch/pair_result.h"
#include "scene/parts.h"
#include "scene/scene.h"
#include "solve/settings.h"

namespace pd {

struct RunOptions {
  SolverSettings solver;
  double tolerance = 0.0;  ///< scene units, > 0
  int jobs = 1;
  double pair_timeout = 0.0;  ///< seconds, 0 = none
  bool quiet = false;         ///< no progress on stderr
  /// Seconds one mesh file may take to read (in a loader process), 0 = none.
  double load_timeout = kDefaultLoadTimeout;
  std::string cache_dir;  ///< cached decompositions (batch/decomposition_cache.h); "" = none
  /// Called in the parent as each pair ends (completion order), e.g. for JSON Lines.
  std::function<void(const PairResult&, const std::vector<Part>&)> on_pair;
  /// Called with a note on how the run went that the user should know (fewer
  /// workers than asked for, ...). None when empty.
  std::function<void(const std::string&)> on_warning;
};

/// Wall time of each stage of run_scene, in seconds.
struct StageTimes {
  double parts = 0.0;        ///< meshes loaded, transformed and hulled
  double broad_phase = 0.0;  ///< candidate pairs found
  double solve = 0.0;        ///< every pair solved (the work queue)
  double refine = 0.0;       ///< nonconvex pairs: mesh tests, decompositions, piece pairs
};

struct RunResult {
  std::vector<Part> parts;
  std::vector<PairResult> pairs;  ///< in (a, b) order: deterministic whatever the jobs
  long all_pairs = 0;             ///< n(n − 1)/2, or the listed pairs
  long culled = 0;                ///< removed by the broad phase
  long unchecked = 0;             ///< never formed: a part of theirs is unusable
  double seconds = 0.0;
  StageTimes stages;
  std::vector<std::string> simulated;  ///< "interference", then "clearance", "motion" if asked
};

RunResult run_scene(const SceneSpec& scene, const RunOptions& options);

/// Encoding of a PairResult between worker and parent (lossless for doubles).
std::string encode_pair_result(const PairResult& r);
PairResult decode_pair_result(const std::string& s);

/// The parent's view of a worker's answer for pair (a, b): the decoded result,
/// or an error result when the worker failed (`ok` false, `payload` its reason)
/// or its payload cannot be decoded. Never throws on a bad payload.
PairResult pair_result_from_worker(bool ok, const std::string& payload, int a, int b,
                                   const std::string& method);

}  // namespace pd
