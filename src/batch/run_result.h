// What a run found: the parts, each pair's result and how the run went. The
// report layer reads this without the pipeline that made it (batch/run.h).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "results/pair_result.h"
#include "results/summary.h"
#include "scene/parts.h"
#include "scene/rules.h"

namespace pd {

/// Shard K of N (batch/shard.h).
struct ShardSpec {
  int index = 1;  ///< K, 1-based
  int total = 1;  ///< N
};

/// Wall time of each stage of run_scene, in seconds.
struct StageTimes {
  double parts = 0.0;        ///< meshes loaded, transformed and hulled
  double broad_phase = 0.0;  ///< candidate pairs found
  double solve = 0.0;        ///< every pair solved (the work queue)
  double refine = 0.0;       ///< nonconvex pairs: mesh tests, decompositions, piece pairs
  double exact = 0.0;        ///< B-rep pairs: certified by the bound or measured on the solids
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

/// What the rules (scene/rules.h) did in a run: each rule's coverage, the
/// pairs they kept out of the check (docs/report-format.md, "rules").
struct RuleCoverage {
  std::shared_ptr<const Rules> rules;
  std::string hash;                  ///< hashes.rules: the rules and every part's labels
  std::vector<long> set_parts;       ///< per set: the scene's parts it selects
  std::vector<long> test_pairs;      ///< per test: checked pairs it covers
  std::vector<long> ignore_pairs;    ///< per ignore rule: pairs it took out of the check
  std::vector<long> expected_pairs;  ///< per expected rule: checked pairs it covers
  long out_of_scope = 0;             ///< broad-phase candidates no test covers
  long ignored = 0;                  ///< candidates an ignore rule took out
  double seconds = 0.0;              ///< resolving the rules and deciding the candidates
};

/// A part's labels (scene/scene.h) and the rule sets it belongs to.
struct PartLabels {
  std::vector<std::string> tags, sets;
  std::string group;
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
  std::optional<ReuseCounts> reuse;    ///< with --reuse: what was taken, why not the rest
  std::optional<ShardManifest> shard;  ///< set by a --shard run
  std::optional<RuleCoverage> rules;   ///< when the run has rules
  std::vector<PartLabels> labels;      ///< per part, when any part has labels or rules
};

}  // namespace pd
