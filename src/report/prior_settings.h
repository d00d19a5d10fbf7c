// The unit and settings an earlier report was written under (--baseline,
// --reuse, and pdcheck merge --baseline), against the run's: depths in another
// unit are refused, other settings are warned about (docs/ci.md).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "report/input_error.h"
#include "report/report_json.h"

namespace pd {

struct PriorSettings {
  std::optional<std::string> units;      ///< the report's `units`
  std::optional<double> tolerance;       ///< its `tolerance`, in its units
  bool auto_tolerance = false;           ///< its `tolerance` is "auto"
  std::optional<nlohmann::json> method;  ///< its `method` object
  /// Its `hashes.rules` ("" when it has hashes but no rules; nullopt: no hashes).
  std::optional<std::string> rules_hash;
};

/// The fields of a report document (absent ones stay unset: nothing to compare).
template <class Json>
PriorSettings prior_settings_of(const Json& report) {
  PriorSettings s;
  if (!report.is_object()) return s;
  if (report.contains("units") && report["units"].is_string())
    s.units = report["units"].template get<std::string>();
  if (report.contains("tolerance") && report["tolerance"].is_number())
    s.tolerance = report["tolerance"].template get<double>();
  s.auto_tolerance = report.contains("tolerance") && report["tolerance"] == "auto";
  if (report.contains("method") && report["method"].is_object())
    s.method = nlohmann::json::parse(report["method"].dump());  // small: the settings only
  if (report.contains("hashes") && report["hashes"].is_object()) {
    const auto& h = report["hashes"];
    s.rules_hash = h.contains("rules") && h["rules"].is_string()
                       ? h["rules"].template get<std::string>()
                       : std::string();
  }
  return s;
}

/// Compares the report `path`, given as `option` ("--baseline"), with the run's
/// context. A report in another unit throws ReportInputError naming both units:
/// its depths, and the run's, are numbers in different units. A different
/// tolerance, method or rules (hashes.rules) is returned as warnings: the comparison stands, but a
/// finding's state may come from the settings rather than from the geometry.
std::vector<std::string> check_prior_settings(const std::string& option, const std::string& path,
                                              const PriorSettings& prior, const ReportContext& run);

}  // namespace pd
