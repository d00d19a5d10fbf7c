// The HTML report through the binary (--html, pdcheck html). Its geometry:
// test_html_geometry.cpp; its page: test_write_html.cpp; the page in a real
// browser: tests/browser/test_html_report.py.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "page_data.h"
#include "shell_run.h"

using namespace pd;
using pd_test::scratch_dir;
using pd_test::shell;
using pd_test::ShellRun;

TEST(HtmlCli, RunAndSavedReportGiveTheSameFindings) {
  const std::string dir = scratch_dir("html_cli");
  const ShellRun run = shell(dir, "\"$PDCHECK\" \"$DEMO\" -q -o r.json --html run.html");
  EXPECT_EQ(run.code, 1) << run.err;
  const ShellRun saved = shell(dir, "\"$PDCHECK\" html r.json -o saved.html");
  EXPECT_EQ(saved.code, 0) << saved.err;
  EXPECT_NE(saved.err.find("wrote saved.html"), std::string::npos) << saved.err;
  const nlohmann::json a = page_data(pd_test::read_text(dir + "/run.html"));
  const nlohmann::json b = page_data(pd_test::read_text(dir + "/saved.html"));
  ASSERT_TRUE(a.is_object() && b.is_object());
  const nlohmann::json report = nlohmann::json::parse(pd_test::read_text(dir + "/r.json"));
  size_t findings = 0;
  for (const auto& p : report["pairs"]) findings += p["status"] != "separated";
  EXPECT_EQ(a["findings"].size(), findings);
  EXPECT_EQ(b["findings"].size(), findings);
  for (size_t k = 0; k < findings; ++k) {
    EXPECT_EQ(a["findings"][k]["fingerprint"], b["findings"][k]["fingerprint"]);
    EXPECT_FALSE(b["findings"][k]["view"]["a"].is_null()) << k;
  }
  EXPECT_EQ(a["findings"][0]["status"], "interference");
  // Nearby parts as context: known ids, never the pair's own parts.
  const auto& context = a["findings"][0]["view"]["context"];
  EXPECT_FALSE(context.empty());
  for (const auto& k : context) {
    const std::string id = a["boxes"][k.get<size_t>()][0];
    EXPECT_NE(id, a["findings"][0]["a"]);
    EXPECT_NE(id, a["findings"][0]["b"]);
  }
}

TEST(HtmlCli, BaselineStatesAndAMovedReport) {
  // With --baseline the page carries the state counts and each finding's state;
  // a report moved beside its scene still finds it.
  const std::string dir = scratch_dir("html_cli_baseline");
  const ShellRun r =
      shell(dir,
            "cp -r \"$(dirname \"$DEMO\")\" demo && cd demo && \"$PDCHECK\" scene.json -q "
            "-o ../old.json; \"$PDCHECK\" scene.json -q -o ../r.json --baseline "
            "../old.json --html ../run.html; cd .. && mkdir moved && cp r.json "
            "demo/r.json && \"$PDCHECK\" html demo/r.json -o moved/p.html");
  EXPECT_EQ(r.code, 0) << r.err;
  const nlohmann::json run = page_data(pd_test::read_text(dir + "/run.html"));
  ASSERT_TRUE(run.is_object());
  EXPECT_EQ(run["summary"]["baseline"]["unchanged"], 3) << run["summary"];
  EXPECT_EQ(run["findings"][0]["baseline_state"], "unchanged");
  const nlohmann::json moved = page_data(pd_test::read_text(dir + "/moved/p.html"));
  ASSERT_TRUE(moved.is_object());
  EXPECT_TRUE(moved["notes"].empty()) << moved["notes"];
  EXPECT_FALSE(moved["findings"][0]["view"]["a"].is_null());
}

TEST(HtmlCli, AReportMovedAwayFromItsSceneSaysWhereItLookedAndTakesScene) {
  // The run in demo/ names its scene "scene.json"; the report then travels
  // alone (a CI artefact) to ci/.
  const std::string dir = scratch_dir("html_cli_scene");
  const ShellRun run = shell(dir,
                             "cp -r \"$(dirname \"$DEMO\")\" demo && cd demo && \"$PDCHECK\" "
                             "scene.json -q -o r.json; cd .. && mkdir ci && mv demo/r.json ci/");
  EXPECT_EQ(run.code, 0) << run.err;
  const ShellRun lost = shell(dir, "\"$PDCHECK\" html ci/r.json -o p.html");
  EXPECT_EQ(lost.code, 2) << lost.err;
  EXPECT_NE(lost.err.find("ci/r.json: its scene \"scene.json\" is not found: not at scene.json "
                          "(as the run named it, from the working directory) nor ci/scene.json "
                          "(beside the report); say where it is with --scene PATH"),
            std::string::npos)
      << lost.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/p.html"));
  const ShellRun found =
      shell(dir, "\"$PDCHECK\" html ci/r.json --scene demo/scene.json -o p.html");
  EXPECT_EQ(found.code, 0) << found.err;
  const nlohmann::json data = page_data(pd_test::read_text(dir + "/p.html"));
  ASSERT_TRUE(data.is_object());
  EXPECT_TRUE(data["notes"].empty()) << data["notes"];
  for (const auto& f : data["findings"]) EXPECT_FALSE(f["view"]["a"].is_null());
  const ShellRun wrong = shell(dir, "\"$PDCHECK\" html ci/r.json --scene nowhere.json -o p.html");
  EXPECT_EQ(wrong.code, 2);
  EXPECT_NE(wrong.err.find("--scene nowhere.json: no such file (the scene of ci/r.json)"),
            std::string::npos)
      << wrong.err;
}

TEST(HtmlCli, AMergeOfMovedShardsTakesScene) {
  // Shards run in demo/, their reports gathered in ci/ (CI artefacts): the
  // merge's --html finds the scene where --scene says.
  const std::string dir = scratch_dir("html_cli_merge_scene");
  const ShellRun shards =
      shell(dir,
            "cp -r \"$(dirname \"$DEMO\")\" demo && cd demo && for k in 1 2; do \"$PDCHECK\" "
            "scene.json -q --shard $k/2 -o shard-$k.json; done; cd .. && mkdir ci && mv "
            "demo/shard-*.json ci/");
  EXPECT_EQ(shards.code, 0) << shards.err;
  const ShellRun lost =
      shell(dir, "\"$PDCHECK\" merge ci/shard-1.json ci/shard-2.json -q -o r.json --html p.html");
  EXPECT_EQ(lost.code, 2) << lost.err;
  EXPECT_NE(lost.err.find("say where it is with --scene PATH"), std::string::npos) << lost.err;
  const ShellRun found =
      shell(dir,
            "\"$PDCHECK\" merge ci/shard-1.json ci/shard-2.json -q -o r.json --html p.html "
            "--scene demo/scene.json");
  EXPECT_EQ(found.code, 1) << found.err;  // the demo's interference
  const nlohmann::json data = page_data(pd_test::read_text(dir + "/p.html"));
  ASSERT_TRUE(data.is_object());
  EXPECT_EQ(data["verdict"]["state"], "fail");
  for (const auto& f : data["findings"]) EXPECT_FALSE(f["view"]["a"].is_null());
}

TEST(HtmlCli, UnreadablePartsAreNamedAndTheRestIsShown) {
  const std::string dir = scratch_dir("html_cli_missing");
  const ShellRun r = shell(dir,
                           "cp -r \"$(dirname \"$DEMO\")\" demo && \"$PDCHECK\" demo/scene.json -q "
                           "-o r.json; rm demo/cover.obj; \"$PDCHECK\" html r.json -o p.html");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("part \"cover\""), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cover.obj"), std::string::npos) << r.err;
  const nlohmann::json data = page_data(pd_test::read_text(dir + "/p.html"));
  ASSERT_TRUE(data.is_object());
  bool noted = false;
  for (const auto& n : data["notes"])
    noted |= n.get<std::string>().find("cover") != std::string::npos;
  EXPECT_TRUE(noted) << data["notes"];
  for (const auto& f : data["findings"])  // the other parts keep their views
    if (f["a"] != "cover" && f["b"] != "cover") {
      EXPECT_FALSE(f["view"]["a"].is_null());
    }
}

TEST(HtmlCli, BadInputsFailBeforeAnyWork) {
  const std::string dir = scratch_dir("html_cli_bad");
  const ShellRun no_report = shell(dir, "\"$PDCHECK\" html none.json -o p.html");
  EXPECT_EQ(no_report.code, 2);
  EXPECT_NE(no_report.err.find("none.json"), std::string::npos) << no_report.err;
  const ShellRun not_report = shell(dir, "\"$PDCHECK\" html \"$DEMO\" -o p.html");
  EXPECT_EQ(not_report.code, 2);
  EXPECT_NE(not_report.err.find("not a pdcheck JSON report"), std::string::npos) << not_report.err;
  const ShellRun bad_path = shell(dir, "\"$PDCHECK\" \"$DEMO\" -q --html missing/p.html");
  EXPECT_EQ(bad_path.code, 2);
  EXPECT_NE(bad_path.err.find("--html"), std::string::npos) << bad_path.err;
  const ShellRun no_three = shell(
      dir,
      "mkdir empty; PDCHECK_THREE_DIR=empty \"$PDCHECK\" \"$DEMO\" -q -o r.json --html p.html");
  EXPECT_EQ(no_three.code, 2);
  EXPECT_NE(no_three.err.find("three.min.js"), std::string::npos) << no_three.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/r.json")) << "the run went ahead";
  const ShellRun stdin_scene =
      shell(dir,
            "printf %s \"{\\\"scene\\\": \\\"-\\\", \\\"pairs\\\": []}\" > s.json; "
            "\"$PDCHECK\" html s.json -o p.html");
  EXPECT_EQ(stdin_scene.code, 2);
  EXPECT_NE(stdin_scene.err.find("standard input"), std::string::npos) << stdin_scene.err;
  const ShellRun bad_type = shell(dir,
                                  "printf \"{\\\"scene\\\": \\\"%s\\\", \\\"pairs\\\": "
                                  "[{\\\"status\\\": 5}]}\" \"$DEMO\" > t.json; "
                                  "\"$PDCHECK\" html t.json -o p.html");
  EXPECT_EQ(bad_type.code, 2);
  EXPECT_NE(bad_type.err.find("t.json: not a pdcheck JSON report"), std::string::npos)
      << bad_type.err;
  const ShellRun no_scene = shell(dir, "\"$PDCHECK\" -q");
  EXPECT_EQ(no_scene.code, 2);
  EXPECT_NE(no_scene.err.find("scene is required"), std::string::npos) << no_scene.err;
}
