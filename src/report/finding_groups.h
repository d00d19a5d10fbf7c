// Findings that share a fix: one item per design problem rather than per pair
// (docs/report-format.md, "Groups"). Computed from the results alone, so a
// run, its shards' merge and a later reader all find the same groups.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "results/pair_result.h"

namespace pd {

/// Whether a finding takes part in a group: it needs a fix (interference,
/// clearance_violation). False positives (tessellation artefacts, nothing to
/// fix), undecided pairs (not known to need one) and errors are in none.
bool needs_fix(Status s);

/// The move of `part` that a member's direction asks for (results/pair_result.h:
/// moving b along +direction clears the pair; a moves along −direction).
Vec3 move_of(const PairResult& r, int part);

/// The suggested fix of a group: moving `part` by `length` along `direction`
/// clears the `covers` members that involve it and whose moves of it are within
/// tol::kGroupMoveAngle of the deepest one's (as a plane estimate: each such
/// member's depth, or clearance shortfall, divided by the cosine between its
/// move and `direction`, the largest of them).
struct SuggestedMove {
  int part = -1;
  Vec3 direction = Vec3::UnitZ();
  double length = 0.0;
  std::vector<size_t> covers;  ///< indices into the pairs, report order
};

struct FindingGroup {
  std::string id;               ///< 32 hex digits from the members' fingerprints
  std::vector<size_t> members;  ///< indices into the pairs, report order
  std::vector<int> parts;       ///< the members' parts, by id
  size_t deepest = 0;           ///< the member with the largest depth (else shortfall)
  SuggestedMove move;
};

struct FindingGroups {
  /// The deepest group first (the deepest member's depth, then its clearance
  /// shortfall), then by id.
  std::vector<FindingGroup> groups;
  std::vector<int> group_of;  ///< per pair: its group's index, or -1
};

/// The groups of a run's findings. Two findings that need a fix are one group
/// when they share a part and their moves of that part are at most
/// tol::kGroupMoveAngle apart; groups are the transitive closure (union-find)
/// of that relation, every such finding in exactly one (alone, if need be).
/// Parts sharing findings whose moves disagree (a part squeezed from two
/// sides) stay separate groups: each needs its own fix. `ids`: the part ids,
/// by index (the pairs' a and b).
FindingGroups group_findings(const std::vector<PairResult>& pairs,
                             const std::vector<std::string>& ids);

}  // namespace pd
