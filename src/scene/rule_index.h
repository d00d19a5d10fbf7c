// Rules resolved against a scene's parts once (scene/rules.h): each part's set
// membership as bits, its group and file as small integers, so that a pair's
// decision (checked or not, by which tests, its tolerance and clearance, an
// expected contact) costs a few bit tests. Applied to candidate pairs only
// (batch/rule_scope.h): never to all n² pairs.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "scene/rules.h"
#include "scene/scene.h"

namespace pd {

/// What the rules say of one pair of parts.
struct PairDecision {
  enum class Scope { kChecked, kOutOfScope, kIgnored };
  Scope scope = Scope::kChecked;
  int ignore = -1;         ///< the ignore rule (index), when kIgnored
  int expected = -1;       ///< the first expected rule covering the pair, or -1
  std::vector<int> tests;  ///< the tests covering the pair (indices, in order)
  /// The tolerance and clearance of the most specific level (the pair's, else
  /// the tests': the smallest tolerance, the largest clearance); nullopt: the scene's.
  std::optional<double> tolerance, clearance;
  int tolerance_test = -1;  ///< the test that gave `tolerance`, or -1
  int tolerance_pair = -1;  ///< the pair rule that gave it (the most specific), or -1
  int clearance_rank = 0;   ///< where `clearance` came from: 1 a test, 2 the pair's rule
};

class RuleIndex {
 public:
  /// Resolves every set against `parts` (scene order). Throws SceneError
  /// (exit 2) naming a set that selects no part, unless it is optional, and a
  /// pair rule naming an unknown part.
  RuleIndex(const Rules& rules, const std::vector<PartSpec>& parts);

  /// The decision for scene parts i and j (i != j; symmetric).
  PairDecision decide(int i, int j) const;
  /// The same into `out`, reusing its storage (the candidates' loop).
  void decide(int i, int j, PairDecision& out) const;
  /// Which rule gave a decision's tolerance: "tests[\"x\"]", "pairs[0]", or "".
  std::string tolerance_rule(const PairDecision& d) const;

  bool in_set(int part, int set) const {
    return (bits_[size_t(part) * words_ + size_t(set) / 64] >> (set % 64)) & 1u;
  }
  /// Parts each set selects.
  const std::vector<long>& set_parts() const { return set_parts_; }
  /// The names of the sets part k belongs to, in the rules' order.
  std::vector<std::string> sets_of(int part) const;
  const Rules& rules() const { return *rules_; }

 private:
  bool covers(const SetPair& s, int i, int j) const;
  const Rules* rules_;
  size_t words_ = 1;
  std::vector<std::uint64_t> bits_;  ///< part-major, words_ per part
  std::vector<int> group_, file_;    ///< per part: an id (-1: none)
  std::vector<long> set_parts_;
  std::unordered_map<std::uint64_t, int> pair_rule_;  ///< (i << 32 | j), i < j -> pairs index
};

}  // namespace pd
