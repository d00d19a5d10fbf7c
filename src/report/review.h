// The CI view of a run: each finding's baseline state and suppression, the
// --fail-on bar, and the exit code they imply. docs/ci.md.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "batch/run_result.h"
#include "exit_code.h"
#include "report/baseline.h"
#include "report/expected_rules.h"
#include "report/fail_on.h"
#include "report/finding_groups.h"
#include "report/suppressions.h"

namespace pd {

struct ReviewOptions {
  std::optional<FailOn> fail_on;  ///< nullopt: default_fail_on
  const Baseline* baseline = nullptr;
  const Suppressions* suppressions = nullptr;
  /// The run's expected-contact rules: a pair naming one (PairResult::expected)
  /// is suppressed by it while its depth is at most the rule's max_depth.
  const ExpectedRules* expected = nullptr;
  bool allow_stale = false;  ///< stale or expired suppressions do not fail the run
  std::string today;         ///< YYYY-MM-DD, for `expires`
  double tolerance = 0.0;    ///< scene units: the `updated` rule
  std::string units = "mm";  ///< the run's, for the lengths in messages
  /// The fingerprints of the scene's pair list, when it has one: other pairs were not checked.
  std::optional<std::set<std::string>> listed;
  /// A run whose every part failed exits 3 like any incomplete run (--allow-empty,
  /// and a shard, judged by its merge); otherwise 2: nothing was checked (batch/empty_input.h).
  bool allow_empty = false;
  /// A shard (--shard): its verdict is its merge's. Its exit code, and its
  /// report's summary.exit_code, are 0 once its report is written, and the
  /// summary says `"verdict": "deferred to pdcheck merge"` (docs/scale-out.md).
  bool deferred = false;
};

/// One pair's review (for findings; clean and failed pairs have neither state nor suppression).
struct PairReview {
  std::string fingerprint;
  std::optional<BaselineState> baseline_state;  ///< findings, with --baseline
  const Suppression* suppressed = nullptr;      ///< the entry that holds for it
  std::optional<Hold> not_holding;              ///< a matching entry that expired or was exceeded
  bool expected_exceeded = false;  ///< its expected-contact rule's max_depth is exceeded
  bool fails = false;              ///< at or above the bar, not suppressed
  std::string group;               ///< its finding group's id (finding_groups.h)
};

/// A suppressions entry that needs attention.
struct SuppressionIssue {
  const Suppression* entry = nullptr;
  std::string kind;  ///< "unmatched", "expired", "exceeded", "unchecked"
  std::string detail;
  bool fails = false;  ///< unmatched or expired, without --allow-stale-suppressions
};

struct Review {
  FailOn fail_on = FailOn::kInterference;
  bool baseline_used = false, suppressions_used = false;
  std::vector<PairReview> pairs;  ///< parallel to RunResult::pairs
  std::vector<GoneFinding> gone;  ///< baseline findings that are no findings now
  std::vector<SuppressionIssue> suppression_issues;
  long state_count[5] = {0, 0, 0, 0, 0};  ///< by BaselineState, gone ones included
  long suppressed = 0, failing = 0;
  FindingGroups groups;  ///< findings that share a fix (finding_groups.h)
  /// Per expected-contact rule (by name): findings it suppressed, and those deeper than its
  /// max_depth.
  std::map<std::string, std::pair<long, long>> expected_counts;
  /// Every part failed (unless allow_empty): bad input; else incomplete wins,
  /// else a finding that fails or a stale suppression (run_exit_code).
  ExitCode exit_code = kExitClean;
  /// The exit code the run would have on its own; a deferred one (a shard) has
  /// exit_code 0 and leaves this to its merge.
  ExitCode own_exit_code = kExitClean;
  bool deferred = false;  ///< ReviewOptions::deferred
};

/// A clearance violation that is a contact: overlapping within the tolerance
/// (no distance), touching (distance 0), or apart by no more than its gap
/// band. An expected-contact rule suppresses it as it does an overlap.
bool contact_violation(const PairResult& r);

/// One pair alone (also for pairs streamed as they finish).
PairReview review_pair(const PairResult& r, const std::vector<Part>& parts,
                       const ReviewOptions& options, FailOn bar);

/// The bar in force: --fail-on, or the default for this run.
FailOn effective_fail_on(const RunResult& run, const ReviewOptions& options);

/// The whole run. `incomplete`: some part or pair was not checked (exit 3 wins).
Review review_run(const RunResult& run, const ReviewOptions& options, bool incomplete);

}  // namespace pd
