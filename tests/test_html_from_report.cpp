// The page of a saved report (report/html_from_report.h) in-process: the scene
// found beside the report, the loader given the report's units and tolerance,
// each finding's part that is gone or unreadable listed as a problem; a report
// of standard input or no report at all refused. Through the binary: test_html.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "report/html_from_report.h"
#include "report/input_error.h"
#include "report_fixture.h"
#include "shell_run.h"

using namespace pd;

TEST(HtmlFromReport, TheSceneBesideTheReportAndEachLostPartNamed) {
  test::ReportFixture f = test::every_status();
  const nlohmann::json doc =
      nlohmann::json::parse(report_json(f.context, f.run).dump());  // scene "scene.json"
  const std::string dir = pd_test::scratch_dir("html_from_report");
  std::ofstream(dir + "/scene.json") << "{}";
  std::string asked;
  std::optional<std::string> units;
  std::optional<double> tolerance;
  const auto load = [&](const std::string& scene, const std::optional<std::string>& u,
                        std::optional<double> t) {
    asked = scene;
    units = u;
    tolerance = t;
    // The scene as it is now: the bolt is gone, the pin cannot be read.
    std::vector<Part> parts;
    for (const char* id : {"frame", "lid <&>", "pin"}) {
      Part p;
      p.id = id;
      p.source = std::string(id) + ".stl";
      parts.push_back(p);
    }
    parts[2].error = "unreadable: truncated";
    return parts;
  };
  const SavedReportPage page = html_from_report_document(doc, dir + "/report.json", load);
  EXPECT_EQ(asked, dir + "/scene.json");
  EXPECT_EQ(units, std::optional<std::string>("mm"));
  EXPECT_EQ(tolerance, std::optional<double>(0.1));
  ASSERT_EQ(page.problems.size(), 2u);
  EXPECT_EQ(page.problems[0], "part \"bolt\" is in the report but not in " + dir +
                                  "/scene.json now: its findings have no 3D view");
  EXPECT_EQ(page.problems[1],
            "part \"pin\" (pin.stl): could not be read: unreadable: truncated; its findings have "
            "no 3D view");
  EXPECT_NE(page.html.find("<html"), std::string::npos);
  EXPECT_NE(page.html.find("no 3D view"), std::string::npos);
}

TEST(HtmlFromReport, AReportOfStandardInputOrNoReportIsRefused) {
  const auto never = [](const std::string&, const std::optional<std::string>&,
                        std::optional<double>) -> std::vector<Part> {
    ADD_FAILURE() << "loaded a scene";
    return {};
  };
  const auto message = [&](const nlohmann::json& doc) -> std::string {
    try {
      html_from_report_document(doc, "r.json", never);
    } catch (const ReportInputError& e) {
      return e.what();
    }
    return "";
  };
  const std::string stdin_scene = message({{"scene", "-"}, {"pairs", nlohmann::json::array()}});
  EXPECT_NE(stdin_scene.find("r.json"), std::string::npos) << stdin_scene;
  EXPECT_NE(stdin_scene.find("standard input"), std::string::npos) << stdin_scene;
  const std::string not_report = message({{"scene", "s.json"}});
  EXPECT_NE(not_report.find("not a pdcheck JSON report"), std::string::npos) << not_report;
  const std::string wrong_type = message({{"scene", 3}, {"pairs", nlohmann::json::array()}});
  EXPECT_NE(wrong_type.find("r.json"), std::string::npos) << wrong_type;
}
