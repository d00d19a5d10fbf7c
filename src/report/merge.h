// pdcheck merge: shard reports (--shard K/N) into the report one run writes
// (docs/scale-out.md). Refuses anything that would make it another report.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "report/fail_on.h"

namespace pd {

/// Missing, duplicated or mismatched shards, or a file that is no shard report:
/// exit 2, the message names the files and what differs.
class MergeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ShardReport {
  std::string path;
  nlohmann::ordered_json doc;
};

/// Reads a shard report (throws MergeError naming the file).
ShardReport read_shard_report(const std::string& path);

struct Merged {
  nlohmann::ordered_json doc;  ///< the report, as docs/report-format.md
  int exit_code = 0;           ///< as one run's: 3 incomplete, 1 a finding at the bar, else 0
  std::string summary_line;    ///< for stderr
};

/// Shards 1..N of one scene, settings and tool version, each exactly once, in any
/// order. The merged report equals the unsharded run's pair for pair; `seconds`
/// and `stage_seconds` are the shards' sums. `fail_on`: as --fail-on (not `new`).
Merged merge_shard_reports(const std::vector<ShardReport>& shards,
                           std::optional<FailOn> fail_on = std::nullopt);

}  // namespace pd
