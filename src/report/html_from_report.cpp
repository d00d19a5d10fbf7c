#include "report/html_from_report.h"

#include <filesystem>
#include <map>
#include <set>

#include "report/input_error.h"
#include "report/json_input.h"
#include "report/write_html.h"

namespace pd {

namespace fs = std::filesystem;

namespace {

// The scene: `given` (pdcheck html --scene) when set, else as the run named it,
// else beside the report (a report moved with its scene). Throws
// ReportInputError naming every place looked at when none exists.
std::string find_scene(const std::string& scene, const std::string& report_path,
                       const std::optional<std::string>& given) {
  std::error_code ec;
  if (given) {
    if (!fs::exists(*given, ec))
      throw ReportInputError("--scene " + *given + ": no such file (the scene of " + report_path +
                             ")");
    return *given;
  }
  const fs::path as_written(scene);
  if (fs::exists(as_written, ec)) return scene;
  std::string looked = scene + " (as the run named it, from the working directory)";
  if (as_written.is_relative()) {
    const fs::path beside = fs::path(report_path).parent_path() / as_written;
    if (fs::exists(beside, ec)) return beside.string();
    looked += " nor " + beside.string() + " (beside the report)";
  }
  throw ReportInputError(report_path + ": its scene \"" + scene + "\" is not found: not at " +
                         looked + "; say where it is with --scene PATH");
}

SavedReportPage page_of(const nlohmann::json& raw, const std::string& report_path,
                        const ScenePartsLoader& load, const std::optional<std::string>& scene) {
  const JsonAt root{raw, report_path, "$"};
  root.object();
  if (!root.has("pairs") || !root.has("scene"))
    root.fail("not a pdcheck JSON report (--format json): no \"pairs\" or \"scene\"");
  root["pairs"].array();
  const std::string scene_name = root["scene"].string();
  if (scene_name == "-" && !scene)
    root["scene"].fail(
        "the scene was read from standard input: its geometry cannot be read "
        "again (write the page during the run with --html, or give the scene's file with "
        "--scene PATH)");
  std::optional<std::string> units;
  if (root.has("units")) units = root["units"].string();
  const std::string scene_path = find_scene(scene_name, report_path, scene);
  std::optional<double> tolerance;
  // Under auto ("auto"), the scene's own: the geometry does not depend on it.
  if (root.has("tolerance") && raw["tolerance"] != "auto") tolerance = root["tolerance"].number();
  std::vector<Part> parts = load(scene_path, units, tolerance);

  SavedReportPage page;
  std::map<std::string, Part*> by_id;
  for (Part& p : parts) by_id.emplace(p.id, &p);
  // A part's convexity as the run measured it where a pair needed it
  // (batch/convexity_on_demand.h): the page draws its hull or its surface alike.
  if (raw.contains("parts") && raw["parts"].is_array())
    for (const auto& p : raw["parts"])
      if (p.is_object() && p.contains("convex") && p["convex"].is_boolean() && p.contains("id"))
        if (const auto it = by_id.find(p["id"].get<std::string>());
            it != by_id.end() && it->second->convexity_on_demand() && !it->second->convex)
          it->second->convex = p["convex"].get<bool>();
  std::set<std::string> named;  // the parts of the report's findings
  for (const auto& p : raw["pairs"])
    if (p.value("status", "") != "separated")
      for (const char* side : {"a", "b"}) named.insert(p.value(side, ""));
  for (const std::string& id : named) {
    const auto it = by_id.find(id);
    if (it == by_id.end())
      page.problems.push_back("part \"" + id + "\" is in the report but not in " + scene_path +
                              " now: its findings have no 3D view");
    else if (it->second->error)
      page.problems.push_back("part \"" + id + "\" (" + it->second->source +
                              "): could not be read: " + *it->second->error +
                              "; its findings have no 3D view");
  }
  page.html = render_html(nlohmann::ordered_json::parse(raw.dump()), parts, page.problems);
  return page;
}

}  // namespace

SavedReportPage html_from_report(const std::string& report_path, const ScenePartsLoader& load,
                                 const std::optional<std::string>& scene) {
  return html_from_report_document(parse_json_input(read_input_file(report_path), report_path),
                                   report_path, load, scene);
}

SavedReportPage html_from_report_document(const nlohmann::json& raw, const std::string& report_path,
                                          const ScenePartsLoader& load,
                                          const std::optional<std::string>& scene) {
  try {
    return page_of(raw, report_path, load, scene);
  } catch (const nlohmann::json::exception& e) {  // a value of the wrong type
    throw ReportInputError(report_path + ": not a pdcheck JSON report: " + e.what());
  }
}

}  // namespace pd
