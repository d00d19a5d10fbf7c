// The pipeline: scene → parts → hulls → candidate pairs → solves → results.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "batch/pair_result.h"
#include "batch/reuse.h"
#include "batch/shard.h"
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
  /// MB one loader process may allocate (kAutoLoadMemory: a share of the machine's; 0 = none).
  double load_memory_mb = kAutoLoadMemory;
  std::string cache_dir;  ///< cached decompositions (batch/decomposition_cache.h); "" = none
  /// Called in the parent as each pair ends (completion order), e.g. for JSON Lines.
  std::function<void(const PairResult&, const std::vector<Part>&)> on_pair;
  /// Called with a note on how the run went that the user should know (fewer
  /// workers than asked for, ...). None when empty.
  std::function<void(const std::string&)> on_warning;
  /// Check only this shard's pairs, loading only their parts (batch/shard.h).
  std::optional<ShardSpec> shard;
  /// Take unchanged pairs' results from an earlier report (batch/reuse.h).
  const PriorResults* reuse = nullptr;
};

/// Wall time of each stage of run_scene, in seconds.
struct StageTimes {
  double parts = 0.0;        ///< meshes loaded, transformed and hulled
  double broad_phase = 0.0;  ///< candidate pairs found
  double solve = 0.0;        ///< every pair solved (the work queue)
  double refine = 0.0;       ///< nonconvex pairs: mesh tests, decompositions, piece pairs
};

/// What a shard's report says about it (docs/report-format.md, "shard").
struct ShardManifest {
  ShardSpec shard;
  long parts_total = 0;         ///< parts of the scene
  long pairs_total = 0;         ///< the scene's n(n − 1)/2, or its listed pairs
  long pairs_planned = 0;       ///< planned pairs of this shard (a superset of its candidates)
  long pairs_checked = 0;       ///< its candidate pairs (the planned ones whose hull boxes touch)
  bool listed = false;          ///< the scene lists its pairs (no broad phase)
  std::vector<int> part_index;  ///< scene index of each of RunResult::parts
  std::vector<int> owned;       ///< scene indices of the parts this shard reports
  long vertices_loaded = 0, vertices_total = 0;
};

struct RunResult {
  std::vector<Part> parts;
  std::vector<PairResult> pairs;  ///< in (a, b) order: deterministic whatever the jobs
  long all_pairs = 0;             ///< n(n − 1)/2, or the listed pairs
  long culled = 0;                ///< removed by the broad phase
  long unchecked = 0;             ///< never formed: a part of theirs is unusable
  double seconds = 0.0;
  StageTimes stages;
  std::vector<std::string> simulated;    ///< "interference", then "clearance", "motion" if asked
  std::vector<std::string> part_hashes;  ///< per part: content hash (batch/content_hashes.h)
  std::string scene_hash, settings_hash;
  long reused = 0;                     ///< pairs taken from --reuse
  std::optional<ShardManifest> shard;  ///< set by a --shard run
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
