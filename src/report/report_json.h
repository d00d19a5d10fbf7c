// The report: JSON (default) and JSON Lines. Format: docs/report-format.md.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "batch/run_result.h"
#include "results/summary.h"

namespace pd {

struct ReportContext {
  std::string scene_path;
  std::string units;
  double tolerance = 0.0;
  SolverSettings solver;
  double load_seconds = 0.0;  ///< reading and parsing the scene (before run_scene)
  std::optional<AutoTolerance> auto_tolerance;  ///< tolerance auto (each pair its own)
  std::string rules_hash;                       ///< hashes.rules of the run's rules; "" = no rules
};

/// The run's tolerance as the report says it: "auto" under tolerance auto
/// (each pair decided against its own band, given beside it), else the number.
nlohmann::ordered_json tolerance_json(const ReportContext& ctx);
/// The same in words: "auto" or "0.05 mm".
std::string tolerance_words(const ReportContext& ctx);

/// The run's counts (results/summary.h).
Summary summarize(const RunResult& r);

nlohmann::ordered_json pair_json(const PairResult& r, const std::vector<Part>& parts);
nlohmann::ordered_json report_json(const ReportContext& ctx, const RunResult& r);
nlohmann::ordered_json summary_json(const Summary& s);
/// The report's `method`: the depth method's name and the settings it uses.
nlohmann::ordered_json method_json(const SolverSettings& s);
/// One line for stderr: "pdcheck: 12 parts, 7 pairs checked: 1 interference, ...".
std::string summary_line(const Summary& s, double seconds);
/// One line for stderr about --reuse FROM: "pdcheck: 4 pair(s) reused from r.json;
/// 2 solved again: 1 with a changed or new part, 1 not among its pairs".
std::string reuse_line(const ReuseCounts& c, const std::string& from);

}  // namespace pd
