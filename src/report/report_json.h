// The report: JSON (default) and JSON Lines. Format: docs/report-format.md.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "batch/run_result.h"

namespace pd {

struct ReportContext {
  std::string scene_path;
  std::string units;
  double tolerance = 0.0;
  SolverSettings solver;
  double load_seconds = 0.0;  ///< reading and parsing the scene (before run_scene)
};

/// Counts per status, parts that failed, and the exit code they imply.
struct Summary {
  long parts = 0, part_errors = 0, all_pairs = 0, culled = 0, candidates = 0;
  long unchecked = 0;  ///< pairs of an unusable part, never formed
  long separated = 0, false_positive = 0, interference = 0, error = 0;
  long clearance_violation = 0;
  long undecided = 0;  ///< pairs whose depth bracket straddles the tolerance
  bool clearance_checked = false;
  /// 3 if anything was unchecked or undecided, else 1 on interference or clearance violation, else
  /// 0
  int exit_code() const;
};
Summary summarize(const RunResult& r);

nlohmann::ordered_json pair_json(const PairResult& r, const std::vector<Part>& parts);
nlohmann::ordered_json report_json(const ReportContext& ctx, const RunResult& r);
nlohmann::ordered_json summary_json(const Summary& s);
/// A shard's manifest (docs/report-format.md, "shard"); checked and pairs
/// counts are the shard's summary.
nlohmann::ordered_json shard_json(const ShardManifest& m);
/// One line for stderr: "pdcheck: 12 parts, 7 pairs checked: 1 interference, ...".
std::string summary_line(const Summary& s, double seconds);

}  // namespace pd
