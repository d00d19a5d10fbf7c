// Sharding a scene (docs/scale-out.md): shard K of N checks a deterministic,
// cost-balanced share of the candidate pairs and loads only the parts they need.
//
// Every shard plans the same way without hulls: a cheap box per part (its
// placed vertices' box, a superset of its hull's), the sort-and-sweep broad
// phase on those boxes (a superset of the run's candidate pairs), pairs ordered
// along the scene's longest axis and cut into N runs of equal expected cost.
// A shard hulls the parts of its pairs and keeps those whose hull boxes touch
// (batch/broad_phase.h: a pure function of the two boxes, so the shards' pairs
// partition exactly the unsharded run's candidates). Every part is also owned by
// one shard, which reports it, so part errors are known once whether or not a
// part has pairs.
#pragma once

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "batch/run_result.h"
#include "geometry/aabb.h"
#include "scene/scene.h"
#include "user_error.h"

namespace pd {

/// Bad --shard / --shard auto input (exit 2).
class ShardError : public UserError {
 public:
  using UserError::UserError;
};

/// "K/N" with 1 <= K <= N (throws ShardError naming the problem).
ShardSpec parse_shard(const std::string& text);

/// --shard auto: CI_NODE_INDEX/CI_NODE_TOTAL (GitLab, 1-based), or
/// SLURM_ARRAY_TASK_ID with `total` (--shard-total) and the array's first index
/// (SLURM_ARRAY_TASK_MIN, else `base`). Refuses when the variables are absent,
/// not integers, out of range, or disagree with `total`. `env` reads a variable
/// (nullptr when unset).
ShardSpec shard_from_environment(const std::function<const char*(const char*)>& env,
                                 std::optional<int> total, std::optional<int> base);

struct ScenePlan {
  int shards = 1;
  bool listed = false;  ///< the scene lists its pairs: every listed pair, no broad phase
  std::vector<std::optional<Aabb>> boxes;  ///< per part; nullopt: its mesh cannot be read
  std::vector<long> vertices;              ///< per part, as read (the cost proxy)
  std::vector<std::pair<int, int>> pairs;  ///< scene indices, a < b, sorted
  std::vector<int> pair_shard;             ///< per pair, 0-based shard
  std::vector<int> owner;                  ///< per part, the 0-based shard that reports it
  long vertices_total = 0;
};

/// The plan every shard computes alike (independent of `threads`). Reads every
/// mesh file once (loader processes, `load_timeout` each) for its box; hulls
/// nothing. `before_load`: fault injection for tests (scene/mesh_loader.h).
ScenePlan plan_scene(const SceneSpec& scene, int shards, int threads, double load_timeout,
                     const MeshLoadHook& before_load = {});

/// The parts shard `shard` (0-based) loads: those of its pairs and those it owns,
/// sorted scene indices.
std::vector<int> shard_parts(const ScenePlan& plan, int shard);

}  // namespace pd
