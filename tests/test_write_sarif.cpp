// The SARIF writer (--sarif, write_sarif.cpp) in process: valid against the
// SARIF 2.1.0 schema (tests/schemas), a result per finding and per pair not
// decided, keyed by the pair fingerprint, levels from the --fail-on bar,
// locations as URIs.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "bcf_check.h"
#include "cli_support.h"
#include "report_fixture.h"
#include "results/fingerprint.h"

using namespace pd;
using namespace pd::test;
using nlohmann::json;

namespace {

/// The run's result for parts a and b.
json result_of(const json& sarif, const std::string& a, const std::string& b) {
  for (const json& r : sarif["runs"][0]["results"])
    if (r["properties"]["a"] == a && r["properties"]["b"] == b) return r;
  return nullptr;
}

}  // namespace

TEST(WriteSarif, ValidAgainstTheSchema) {
  ReportFixture f = every_status();
  const std::string path = process_temp("run.sarif");
  std::ofstream(path) << render_sarif(f.input());
  bool skip = false;
  const std::string errors = validate_json(kSource + "/tests/schemas/sarif-2.1.0.json", path, skip);
  PD_REQUIRE_TOOL(!skip, "python3-jsonschema");
  EXPECT_EQ(errors, "");
}

TEST(WriteSarif, AResultPerFindingAndPairNotDecided) {
  ReportFixture f = every_status();
  const json sarif = json::parse(render_sarif(f.input()));
  const json& run = sarif["runs"][0];
  // Two interferences, the false positive, the undecided and the failed pair;
  // not the separated one.
  ASSERT_EQ(run["results"].size(), 5u) << run["results"].dump(1);
  EXPECT_TRUE(result_of(sarif, "frame", "bolt").is_null());
  const json lid = result_of(sarif, "frame", "lid <&>");
  ASSERT_TRUE(lid.is_object());
  EXPECT_EQ(lid["ruleId"], "interference");
  EXPECT_EQ(run["tool"]["driver"]["rules"][lid["ruleIndex"].get<int>()]["id"], "interference");
  EXPECT_EQ(lid["level"], "error");  // fails the default bar
  EXPECT_EQ(lid["partialFingerprints"]["pdcheckPair/v1"], pair_fingerprint("frame", "lid <&>"));
  EXPECT_EQ(lid["properties"]["depth"], 1.0);
  EXPECT_EQ(lid["properties"]["depth_source"], "hull");  // which quantity the depth is
  EXPECT_FALSE(lid["properties"].contains("depth_bounds"));
  const json undecided = result_of(sarif, "lid <&>", "bolt");
  EXPECT_EQ(undecided["properties"]["depth_bounds"], json({0.05, 0.2}));
  EXPECT_EQ(lid["properties"]["direction"], json::array({0.0, 0.0, 1.0}));
  EXPECT_EQ(result_of(sarif, "frame", "pin")["level"], "note");      // a false positive
  EXPECT_EQ(result_of(sarif, "lid <&>", "bolt")["level"], "error");  // undecided
  const json failed = result_of(sarif, "pin", "bolt");
  EXPECT_EQ(failed["ruleId"], "error");
  EXPECT_FALSE(failed["properties"].contains("depth"));  // an error has no depth
  // The run did not check everything: exit 3, and the failed part is a notification.
  EXPECT_EQ(run["invocations"][0]["exitCode"], 3);
  EXPECT_EQ(run["invocations"][0]["executionSuccessful"], false);
  const json& notes = run["invocations"][0]["toolExecutionNotifications"];
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0]["message"]["text"], "part bad could not be used: unreadable: no such file");
  EXPECT_EQ(run["properties"]["fail_on"], "interference");
}

TEST(WriteSarif, TheBarSetsLevels) {
  ReportFixture f = every_status();
  f.options.fail_on = FailOn::kAny;
  const json sarif = json::parse(render_sarif(f.input()));
  EXPECT_EQ(result_of(sarif, "frame", "pin")["level"], "error");
  for (const json& rule : sarif["runs"][0]["tool"]["driver"]["rules"])
    if (rule["id"] == "false_positive") {
      EXPECT_EQ(rule["defaultConfiguration"]["level"], "error");
    }
  f.options.fail_on = FailOn::kNone;
  const json none = json::parse(render_sarif(f.input()));
  EXPECT_EQ(result_of(none, "frame", "lid <&>")["level"], "warning");
  EXPECT_EQ(result_of(none, "pin", "bolt")["level"], "error");  // not checked: always an error
}

TEST(WriteSarif, LocationsAreEscapedUrisOnePerFile) {
  ReportFixture f;
  f.context.scene_path = "scenes/my scene.json";
  f.part("a").source = "meshes/a b#1.stl";
  f.part("b");  // inline: the scene file is its location
  f.part("c").source = "meshes/a b#1.stl";
  f.pair(0, 1, Status::kInterference, 1.0);
  f.pair(0, 2, Status::kInterference, 1.0);
  const json sarif = json::parse(render_sarif(f.input()));
  const json& results = sarif["runs"][0]["results"];
  ASSERT_EQ(results.size(), 2u);
  const json& ab = results[0]["locations"];
  ASSERT_EQ(ab.size(), 2u);
  EXPECT_EQ(ab[0]["physicalLocation"]["artifactLocation"]["uri"], "meshes/a%20b%231.stl");
  EXPECT_EQ(ab[1]["physicalLocation"]["artifactLocation"]["uri"], "scenes/my%20scene.json");
  EXPECT_EQ(results[1]["locations"].size(), 1u);  // both parts from one file: one location
  // An absolute path outside the working directory is a file URI.
  f.run.parts[0].source = "/nonexistent-root/x.stl";
  const json abs = json::parse(render_sarif(f.input()));
  EXPECT_EQ(
      abs["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["artifactLocation"]["uri"],
      "file:///nonexistent-root/x.stl");
}
