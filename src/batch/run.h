// The pipeline: scene → parts → hulls → candidate pairs → solves → results.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "batch/reuse.h"
#include "batch/run_result.h"
#include "batch/shard.h"
#include "results/codec.h"
#include "scene/parts.h"
#include "scene/scene.h"
#include "solve/settings.h"

namespace pd {

/// Tests only (fault injection): the product never sets these. Each runs in a
/// worker process, to make it crash or stall as a solver or a reader could.
struct FaultHooks {
  /// Before a loader reads the mesh file at this path (scene/mesh_loader.h).
  MeshLoadHook before_mesh_load;
  /// Before the pair of parts (a, b) is solved.
  std::function<void(const Part& a, const Part& b)> before_pair_solve;
};

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
  /// MB the stages that hold part surfaces (the refinement's distances) keep
  /// for reuse across a part's pairs; what a running pair needs comes on top.
  double memory_mb = 1024;
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
  FaultHooks faults;  ///< tests only
};

RunResult run_scene(const SceneSpec& scene, const RunOptions& options);

/// The parent's view of a worker's answer for pair (a, b) (results/codec.h's
/// complete encoding): the decoded result,
/// or an error result when the worker failed (`ok` false, `payload` its reason)
/// or its payload cannot be decoded. Never throws on a bad payload.
PairResult pair_result_from_worker(bool ok, const std::string& payload, int a, int b,
                                   const std::string& method);

}  // namespace pd
