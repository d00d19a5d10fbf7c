// A run's counts and the exit code they imply (docs/report-format.md, "summary").
#pragma once

#include <map>
#include <optional>
#include <string>

#include "exit_code.h"
#include "results/pair_result.h"

namespace pd {

/// --reuse (docs/scale-out.md): the candidate pairs taken from the earlier
/// report, and for every other one why it was solved again.
struct ReuseCounts {
  long reused = 0;
  /// Pairs solved again, by reason (batch/reuse.h, reuse_miss_key): "settings",
  /// "part_changed", "new_pair", "error", "pair_checks".
  std::map<std::string, long> solved;
};

/// Counts per status, parts that failed, and the exit code they imply.
struct Summary {
  long parts = 0, part_errors = 0, all_pairs = 0, culled = 0, candidates = 0;
  long unchecked = 0;  ///< pairs of an unusable part, never formed
  long separated = 0, false_positive = 0, interference = 0, error = 0;
  long clearance_violation = 0;
  long undecided = 0;  ///< pairs whose depth bracket straddles the tolerance
  bool clearance_checked = false;
  /// Rules (docs/scene-format.md): broad-phase candidates no test covers, and
  /// those an ignore rule took out. Neither solved, neither culled nor clean.
  long out_of_scope = 0, ignored = 0;
  bool rules_given = false;
  std::optional<ReuseCounts> reuse;  ///< a run with --reuse

  /// Counts one pair of this status.
  void add(Status s);
  /// Some part or pair was not checked, or a pair not decided.
  bool incomplete() const { return error > 0 || undecided > 0 || part_errors > 0 || unchecked > 0; }
  /// A finding: an interference or a clearance violation.
  bool has_findings() const { return interference > 0 || clearance_violation > 0; }
  /// Before any review (--fail-on, baseline, suppressions; report/review.h).
  ExitCode exit_code() const { return run_exit_code(incomplete(), has_findings()); }
};

}  // namespace pd
