// Rules applied to a run's candidate pairs (docs/scene-format.md, "Rules"):
// resolved once against the scene's parts (scene/rule_index.h), then each
// candidate pair decided by a few bit tests. Only candidates are decided, so
// the counts are defined over them: a pair whose boxes do not touch is culled
// whatever the rules say (the broad phase proved it clean); a candidate no
// test covers is out of scope, one an ignore rule matches is ignored; neither
// is solved, neither counts as culled or clean.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "batch/pair_solve.h"
#include "batch/run_result.h"
#include "batch/run_stages.h"
#include "scene/rule_index.h"

namespace pd {

/// The rules of a run, resolved, and the decisions of its checked pairs.
class RuleScope {
 public:
  /// Resolves the scene's rules (throws SceneError: a set that selects no
  /// part, a pair rule naming an unknown part). `loaded`: the scene index of
  /// each of the run's parts (empty: every part, in order).
  RuleScope(const SceneSpec& scene, std::vector<int> loaded);

  /// Drops the out-of-scope and ignored pairs from `c` (their counts go to
  /// the coverage) and keeps the decision of each pair that stays.
  void apply(CandidatePairs& c);

  /// `base` with each checked pair's tolerance and clearance from its rules
  /// (the most specific level wins; docs/scene-format.md).
  std::function<PairChecks(int, int)> pair_checks(std::function<PairChecks(int, int)> base) const;

  /// Names the rules of a solved (or reused) pair in `r`: its tests and expected contact.
  void note(PairResult& r) const;

  /// The coverage so far (counts of the pairs applied).
  RuleCoverage& coverage() { return coverage_; }
  const RuleIndex& index() const { return index_; }

 private:
  /// A kept pair's decision, compact: its tests are tests_[tests_begin, tests_end).
  struct Kept {
    std::optional<double> tolerance, clearance;
    int tolerance_test = -1, tolerance_pair = -1, clearance_rank = 0, expected = -1;
    std::uint32_t tests_begin = 0, tests_end = 0;
  };
  const Kept* decision(int a, int b) const;
  std::chrono::steady_clock::time_point start_;  ///< resolution timed from here
  std::shared_ptr<const Rules> rules_;
  RuleIndex index_;
  std::vector<int> loaded_;
  std::vector<std::uint64_t> keys_;  ///< kept pairs, local (a << 32 | b), a < b, sorted
  std::vector<Kept> kept_;           ///< parallel to keys_
  std::vector<int> tests_;
  RuleCoverage coverage_;
  std::unordered_set<std::uint64_t> own_clearance_;  ///< scene pairs of checks.clearance.pairs
};

/// hashes.rules: the rules as read and every part's id, tags, group and file
/// (what the sets select by), in scene order.
std::string rules_hash(const SceneSpec& scene);

}  // namespace pd
