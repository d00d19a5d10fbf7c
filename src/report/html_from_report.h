// `pdcheck html REPORT.json -o PAGE.html`: the page of a saved JSON report,
// its geometry read again from the report's scene.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scene/parts.h"

namespace pd {

struct SavedReportPage {
  std::string html;
  /// What has no 3D view and why, one line each naming the part (and its file):
  /// a part that could not be read, or one the scene no longer has.
  std::vector<std::string> problems;
};

/// Reads a report's scene again and builds its parts: `scene_path` as found,
/// `units` and `tolerance` the report's when it has them (scene/parts.h,
/// load_scene_parts, bound to the run's threads and load timeout). The page
/// renders what it is given: loading stays with the caller.
using ScenePartsLoader = std::function<std::vector<Part>(const std::string& scene_path,
                                                         const std::optional<std::string>& units,
                                                         std::optional<double> tolerance)>;

/// Reads the JSON report at `report_path`, finds its scene and has `load` build
/// the scene's parts, and renders the page. The scene is `scene` when given
/// (pdcheck html --scene: a report moved without its paths, a CI artefact),
/// else the report's "scene" as written (relative to the working directory of
/// the run), else relative to the report's own directory. Throws
/// ReportInputError (the report unreadable or not a pdcheck JSON report; its
/// scene found nowhere: the message names each place looked at and --scene),
/// SceneError (the scene unreadable), HtmlAssetError (three.js missing). A part
/// that cannot be read costs only its own 3D view: it is listed in `problems`
/// and on the page.
SavedReportPage html_from_report(const std::string& report_path, const ScenePartsLoader& load,
                                 const std::optional<std::string>& scene = std::nullopt);

/// The same for a report held in memory (pdcheck merge --html): `report_path`
/// stands for where it is saved, in messages and to find the scene beside it.
SavedReportPage html_from_report_document(const nlohmann::json& report,
                                          const std::string& report_path,
                                          const ScenePartsLoader& load,
                                          const std::optional<std::string>& scene = std::nullopt);

}  // namespace pd
