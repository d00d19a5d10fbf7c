// `pdcheck html REPORT.json -o PAGE.html`: the page of a saved JSON report,
// its geometry read again from the report's scene.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scene/mesh_loader.h"

namespace pd {

struct SavedReportPage {
  std::string html;
  /// What has no 3D view and why, one line each naming the part (and its file):
  /// a part that could not be read, or one the scene no longer has.
  std::vector<std::string> problems;
};

/// Reads the JSON report at `report_path` and its scene (the report's "scene":
/// as written, i.e. relative to the working directory of the run, else relative
/// to the report's own directory), loads and hulls the scene's parts (`threads`,
/// `load_timeout` as for a run) and renders the page. Throws ReportInputError
/// (the report unreadable or not a pdcheck JSON report), SceneError (the scene
/// unreadable), HtmlAssetError (three.js missing). A part that cannot be read
/// costs only its own 3D view: it is listed in `problems` and on the page.
SavedReportPage html_from_report(const std::string& report_path, int threads = 1,
                                 double load_timeout = kDefaultLoadTimeout);

/// The same for a report held in memory (pdcheck merge --html): `report_path`
/// stands for where it is saved, in messages and to find the scene beside it.
SavedReportPage html_from_report_document(const nlohmann::json& report,
                                          const std::string& report_path, int threads = 1,
                                          double load_timeout = kDefaultLoadTimeout);

}  // namespace pd
