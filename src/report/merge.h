// pdcheck merge: shard reports (--shard K/N) into the report one run writes
// (docs/scale-out.md). Refuses anything that would make it another report.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "batch/run_result.h"
#include "report/report_json.h"
#include "report/review.h"
#include "user_error.h"

namespace pd {

/// Missing, duplicated or mismatched shards, or a file that is no shard report:
/// exit 2, the message names the files and what differs.
class MergeError : public UserError {
 public:
  using UserError::UserError;
};

struct ShardReport {
  std::string path;
  nlohmann::ordered_json doc;
};

/// Reads a shard report (throws MergeError naming the file).
ShardReport read_shard_report(const std::string& path);

/// The run the shards make together, as one run would have it: its report and
/// what the other writers (JUnit, SARIF, suppressions; writer.h) read.
struct Merged {
  nlohmann::ordered_json doc;  ///< the report, as docs/report-format.md
  std::string summary_line;    ///< for stderr
  ReportContext context;       ///< scene, units, tolerance
  RunResult run;  ///< parts (id, source, vertices, warnings, error, box; no geometry) and pairs
  ReviewOptions review_options;  ///< the caller's, with the report's tolerance and pair list
  Review review;                 ///< its exit_code is the merge's: as one run's
  /// The reports' expected-contact rules, which review_options points to.
  std::shared_ptr<const ExpectedRules> expected;
};

/// Shards 1..N of one scene, settings and tool version, each exactly once, in any
/// order. The merged report equals the unsharded run's pair for pair; `seconds`
/// and `stage_seconds` are the shards' sums. `review`: as for a run (--baseline,
/// --suppressions, --fail-on; review_inputs.h); its baseline and suppressions
/// must outlive the result.
Merged merge_shard_reports(const std::vector<ShardReport>& shards,
                           const ReviewOptions& review = {});

}  // namespace pd
