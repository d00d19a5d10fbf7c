// The nightly CI loop end to end through the binary: baseline, suppressions,
// --fail-on, JUnit and SARIF (validated against their schemas). docs/ci.md.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_support.h"
#include "cube_json.h"

using nlohmann::json;
using namespace pd::test;

using pd_test::cube_json;

namespace {

// A frame with a press-fit bushing (0.5 deep: an accepted interference), a lid
// resting on top, a bolt far away. `lid_z` moves the lid: 10 rests, 9 sinks 1.0 in.
std::string assembly(const std::string& name, double lid_z, const json& extra = json::array()) {
  json parts = {cube_json("frame", 0, 0, 0, 10), cube_json("bushing", 9.5, 2, 2, 4),
                cube_json("lid", 0, 0, lid_z, 10), cube_json("bolt", 40, 0, 0, 2)};
  for (const auto& p : extra) parts.push_back(p);
  return write_temp(name, json{{"units", "mm"}, {"tolerance", 0.1}, {"parts", parts}}.dump());
}

// The nightly loop's assembly adds a clip 0.3 into the frame's side: a known
// interference that nobody suppressed.
std::string loop_assembly(const std::string& name, double lid_z) {
  return assembly(name, lid_z, json::array({cube_json("clip", -1.7, 6, 6, 2)}));
}

json read_json(const std::string& path) {
  return json::parse(read_text(path));
}

std::map<std::string, json> pairs_by_name(const json& report) {
  std::map<std::string, json> m;
  for (const auto& p : report["pairs"])
    m[std::min(p["a"].get<std::string>(), p["b"].get<std::string>()) + "/" +
      std::max(p["a"].get<std::string>(), p["b"].get<std::string>())] = p;
  return m;
}

std::string tmp(const std::string& name) {
  const std::string p = process_dir() + name;
  std::remove(p.c_str());
  return p;
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

// docs/ci.md's nightly loop: run 1 writes a report and a starting suppressions
// file; a reviewer accepts the press fit; the lid moves; run 2 fails on the new
// finding alone, and its JUnit and SARIF validate.
TEST(CiLoop, NightlyLoopFailsOnlyOnTheNewFinding) {
  const std::string r1 = tmp("loop_r1.json"), sup = tmp("loop_sup.json");
  const CliResult run1 =
      pdcheck(loop_assembly("loop1.json", 10.0) + " -q -o " + r1 + " --write-suppressions " + sup);
  ASSERT_EQ(run1.code, 1) << run1.err;  // the press fit is an interference
  json s = read_json(sup);
  ASSERT_EQ(s["suppressions"].size(), 2u) << s.dump();  // the bushing, then the clip
  EXPECT_EQ(s["suppressions"][0]["b"], "bushing");
  EXPECT_EQ(s["suppressions"][0]["reason"], "");
  // An unreviewed file is rejected: the reason is required.
  const CliResult unreviewed =
      pdcheck(loop_assembly("loop1b.json", 10.0) + " -q --suppressions " + sup);
  EXPECT_EQ(unreviewed.code, 2);
  EXPECT_NE(unreviewed.err.find(sup + ": $.suppressions[0].reason: must say why"),
            std::string::npos)
      << unreviewed.err;
  s["suppressions"][0]["reason"] = "press fit of the bushing, drawing 4711";
  s["suppressions"][0]["owner"] = "mech-team";
  s["suppressions"].erase(1);  // the clip is not accepted: it stays a finding
  std::ofstream(sup) << s.dump(2);
  bool no_validator = false;
  EXPECT_EQ(validate_json(kSource + "/docs/suppressions.schema.json", sup, no_validator), "");

  // Same geometry again: nothing new, the press fit is suppressed.
  const std::string same = tmp("loop_same.json");
  const CliResult calm = pdcheck(loop_assembly("loop2a.json", 10.0) + " -q -o " + same +
                                 " --baseline " + r1 + " --suppressions " + sup + " --fail-on new");
  EXPECT_EQ(calm.code, 0) << calm.err;
  EXPECT_EQ(read_json(same)["summary"]["baseline"]["unchanged"], 2);

  // The lid sinks 1 mm into the frame.
  const std::string r2 = tmp("loop_r2.json"), junit = tmp("loop.junit.xml"),
                    sarif = tmp("loop.sarif");
  const CliResult run2 =
      pdcheck(loop_assembly("loop2.json", 9.0) + " -o " + r2 + " --baseline " + r1 +
              " --suppressions " + sup + " --fail-on new --junit " + junit + " --sarif " + sarif);
  ASSERT_EQ(run2.code, 1) << run2.err;
  // stderr names the new finding and nothing else as failing.
  EXPECT_EQ(count(run2.err, "fails --fail-on new"), 1u) << run2.err;
  EXPECT_NE(run2.err.find("fails --fail-on new: frame / lid: interference: depth 1 mm"),
            std::string::npos)
      << run2.err;
  const json rep = read_json(r2);
  const auto p = pairs_by_name(rep);
  EXPECT_EQ(p.at("frame/lid")["baseline_state"], "new");
  EXPECT_FALSE(p.at("frame/lid").contains("suppressed"));
  EXPECT_EQ(p.at("bushing/frame")["baseline_state"], "unchanged");
  EXPECT_EQ(p.at("bushing/frame")["suppressed"]["reason"],
            "press fit of the bushing, drawing 4711");
  EXPECT_EQ(p.at("clip/frame")["status"], "interference");  // known, unsuppressed, not new
  EXPECT_EQ(p.at("clip/frame")["baseline_state"], "unchanged");
  EXPECT_FALSE(p.at("clip/frame").contains("suppressed"));
  EXPECT_EQ(rep["summary"]["failing"], 1);
  EXPECT_EQ(rep["summary"]["exit_code"], 1);
  EXPECT_EQ(rep["summary"]["baseline"]["new"], 1);
  bool skip = false;
  EXPECT_EQ(validate_json(kSource + "/docs/report.schema.json", r2, skip), "");

  // JUnit: valid against the Jenkins schema; one failure, the lid's; one skipped.
  PD_REQUIRE_TOOL(have_command("xmllint"), "xmllint (libxml2-utils)");
  EXPECT_EQ(validate_xml(kSource + "/tests/schemas/jenkins-junit.xsd", junit), "");
  const std::string xml = read_text(junit);
  EXPECT_EQ(count(xml, "<failure "), 1u) << xml;
  EXPECT_NE(xml.find("<failure type=\"interference\" message=\"frame / lid: interference"),
            std::string::npos)
      << xml;
  EXPECT_EQ(count(xml, "<skipped>"), 1u);
  // SARIF: valid against the SARIF 2.1.0 schema; the new result and the suppressed one.
  EXPECT_EQ(validate_json(kSource + "/tests/schemas/sarif-2.1.0.json", sarif, skip), "");
  PD_REQUIRE_TOOL(!skip, "python3-jsonschema");
  const json sr = read_json(sarif);
  int news = 0, suppressed = 0;
  for (const auto& res : sr["runs"][0]["results"]) {
    if (res.value("baselineState", "") == "new" && res["level"] == "error") ++news;
    if (res.contains("suppressions")) {
      ++suppressed;
      EXPECT_EQ(res["suppressions"][0]["kind"], "external");
      EXPECT_EQ(res["suppressions"][0]["justification"], "press fit of the bushing, drawing 4711");
    }
  }
  EXPECT_EQ(news, 1);
  EXPECT_EQ(suppressed, 1);
  EXPECT_EQ(sr["runs"][0]["invocations"][0]["executionSuccessful"], true);
}

TEST(CiLoop, SarifIsReadBackByTheSarifMultitool) {
  const std::string tool = std::string(PDCHECK_BINARY_DIR) +
                           "/tools/sarif-multitool/node_modules/"
                           "@microsoft/sarif-multitool-linux/Sarif.Multitool";
  PD_REQUIRE_TOOL(access(tool.c_str(), X_OK) == 0,
                  "the SARIF multitool (npm @microsoft/sarif-multitool-linux)");
  const std::string r1 = tmp("mt_r1.json"), sarif = tmp("mt.sarif"), out = tmp("mt_validate.sarif");
  ASSERT_EQ(pdcheck(assembly("mt1.json", 10.0) + " -q -o " + r1).code, 1);
  const CliResult r =
      pdcheck(assembly("mt2.json", 9.0) + " -q --baseline " + r1 + " --sarif " + sarif);
  ASSERT_EQ(r.code, 1) << r.err;
  const CliResult v =
      shell(tool + " validate " + sarif + " --output " + out + " --log ForceOverwrite");
  EXPECT_EQ(v.code, 0) << v.out << v.err;
  // The validator's own log lists no schema errors (rule SARIF1011 and the like).
  const json log = read_json(out);
  for (const auto& res : log["runs"][0]["results"])
    EXPECT_NE(res.value("level", "warning"), "error") << res.dump();
}

TEST(CiLoop, UnknownIsNeverResolvedByAbsence) {
  const std::string r1 = tmp("unk_r1.json"), r2 = tmp("unk_r2.json");
  // CliResult 1: the lid overlaps the frame, the bushing too.
  ASSERT_EQ(pdcheck(assembly("unk1.json", 9.0) + " -q -o " + r1).code, 1);
  // CliResult 2: the lid's mesh cannot be read; the bushing pair is left out of the
  // scene's pair list; the bolt is still checked.
  json scene = json::parse(read_text(assembly("unk2.json", 9.0)));
  for (auto& p : scene["parts"])
    if (p["id"] == "lid") {
      p.erase("vertices");
      p["mesh"] = "no/such/lid.stl";
    }
  scene["pairs"] = json::array({json::array({"frame", "bolt"})});
  const CliResult r =
      pdcheck(write_temp("unk2.json", scene.dump()) + " -q -o " + r2 + " --baseline " + r1);
  EXPECT_EQ(r.code, 3) << r.err;
  const json rep = read_json(r2);
  std::map<std::string, std::string> gone;
  for (const auto& g : rep["baseline"]["gone"])
    gone[g["a"].get<std::string>() + "/" + g["b"].get<std::string>()] =
        g["baseline_state"].get<std::string>() + ": " + g["reason"].get<std::string>();
  EXPECT_EQ(gone.at("frame/lid").rfind("unknown: part \"lid\" failed to load", 0), 0u)
      << gone.at("frame/lid");
  EXPECT_EQ(gone.at("frame/bushing"),
            "unknown: the pair was not checked (not among the scene's pairs)");
  EXPECT_EQ(rep["summary"]["baseline"]["absent"], 0);
  // SARIF says the run was incomplete.
  const std::string sarif = tmp("unk.sarif");
  EXPECT_EQ(
      pdcheck(write_temp("unk2.json", scene.dump()) + " -q --baseline " + r1 + " --sarif " + sarif)
          .code,
      3);
  EXPECT_EQ(read_json(sarif)["runs"][0]["invocations"][0]["executionSuccessful"], false);
}

TEST(CiLoop, AbsentWhenCheckedAndClean) {
  const std::string r1 = tmp("abs_r1.json"), r2 = tmp("abs_r2.json");
  ASSERT_EQ(pdcheck(assembly("abs1.json", 9.0) + " -q -o " + r1).code, 1);
  // The lid back on top (touching: separated) and the bushing out of the frame (culled).
  json scene = json::parse(read_text(assembly("abs2.json", 10.0)));
  scene["parts"][1] = cube_json("bushing", 20, 2, 2, 4);
  const CliResult r = pdcheck(write_temp("abs2.json", scene.dump()) + " -q -o " + r2 +
                              " --baseline " + r1 + " --fail-on new");
  EXPECT_EQ(r.code, 0) << r.err;
  const json rep = read_json(r2);
  EXPECT_EQ(rep["summary"]["baseline"]["absent"], 2) << rep["baseline"].dump();
  for (const auto& g : rep["baseline"]["gone"]) EXPECT_EQ(g["baseline_state"], "absent");
}

TEST(CiLoop, StaleSuppressionsFailUnlessAllowed) {
  const std::string sup = write_temp("stale.json", R"({"suppressions": [
    {"a": "frame", "b": "bushing", "reason": "press fit"},
    {"a": "frame", "b": "bolt", "reason": "was a clash once"}]})");
  const CliResult r = pdcheck(assembly("stale_scene.json", 10.0) + " --suppressions " + sup);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("$.suppressions[1] (frame / bolt): unmatched"), std::string::npos) << r.err;
  // The review says how many findings the file suppressed.
  EXPECT_NE(r.err.find(sup + ": 1 finding(s) suppressed"), std::string::npos) << r.err;
  EXPECT_EQ(pdcheck(assembly("stale_scene.json", 10.0) + " -q --suppressions " + sup +
                    " --allow-stale-suppressions")
                .code,
            0);
  const std::string expired = write_temp("expired.json", R"({"suppressions": [
    {"a": "frame", "b": "bushing", "reason": "press fit", "expires": "2001-01-01"}]})");
  const CliResult e = pdcheck(assembly("stale_scene.json", 10.0) + " --suppressions " + expired +
                              " --allow-stale-suppressions");
  EXPECT_EQ(e.code, 1) << e.err;  // allowed as stale, but the finding is back
  const std::string deep = write_temp("deep.json", R"({"suppressions": [
    {"a": "frame", "b": "bushing", "reason": "press fit", "max_depth": 0.3}]})");
  EXPECT_EQ(pdcheck(assembly("stale_scene.json", 10.0) + " -q --suppressions " + deep).code, 1);
}

TEST(CiLoop, BadCiInputsExitTwo) {
  const std::string scene = assembly("bad_inputs.json", 10.0);
  const CliResult nb = pdcheck(scene + " -q --fail-on new");
  EXPECT_EQ(nb.code, 2);
  EXPECT_NE(nb.err.find("--fail-on new needs --baseline"), std::string::npos) << nb.err;
  EXPECT_EQ(pdcheck(scene + " -q --fail-on sometimes").code, 2);
  const CliResult mb = pdcheck(scene + " -q --baseline " +
                               write_temp("bad_base.json", R"({"pairs": [{"a": "x"}]})"));
  EXPECT_EQ(mb.code, 2);
  EXPECT_NE(mb.err.find("bad_base.json: $.pairs[0]: missing required key \"b\""), std::string::npos)
      << mb.err;
  const CliResult ms = pdcheck(scene + " -q --suppressions " +
                               write_temp("bad_sup.json", R"({"suppressions": [{"a": "x", "b": "y",
                          "reason": "r", "max_depth": "deep"}]})"));
  EXPECT_EQ(ms.code, 2);
  EXPECT_NE(ms.err.find("bad_sup.json: $.suppressions[0].max_depth: must be a number"),
            std::string::npos)
      << ms.err;
  EXPECT_EQ(pdcheck(scene + " -q --baseline /nonexistent/old.json").code, 2);
  EXPECT_EQ(pdcheck(scene + " -q --junit /nonexistent-dir/j.xml").code, 2);
}

TEST(CiLoop, FailOnBars) {
  // The resting lid touches (separated); the press fit is an interference; a
  // shim 0.05 deep in the frame is a false positive.
  const std::string scene =
      assembly("bars.json", 10.0, json::array({cube_json("shim", -1.95, 2, 2, 2)}));
  EXPECT_EQ(pdcheck(scene + " -q").code, 1);
  EXPECT_EQ(pdcheck(scene + " -q --fail-on interference").code, 1);
  EXPECT_EQ(pdcheck(scene + " -q --fail-on none").code, 0);
  const std::string accept = write_temp("bars_sup.json", R"({"suppressions": [
    {"a": "bushing", "b": "frame", "reason": "press fit"}]})");
  EXPECT_EQ(pdcheck(scene + " -q --suppressions " + accept).code, 0);
  EXPECT_EQ(pdcheck(scene + " -q --suppressions " + accept + " --fail-on clearance").code, 0);
  EXPECT_EQ(pdcheck(scene + " -q --suppressions " + accept + " --fail-on any").code, 1);
}

// A unit the input declares is never reinterpreted, and a prior report in
// another unit is refused: its depths are numbers in another unit (issue 25).
TEST(CiCli, UnitsAreNeverReinterpreted) {
  const std::string mm_scene = assembly("units_mm.json", 9);
  const CliResult clash = pdcheck(mm_scene + " -q --units in");
  EXPECT_EQ(clash.code, 2) << clash.err;
  EXPECT_NE(clash.err.find("units_mm.json: units: the scene declares \"mm\" but --units says "
                           "\"in\""),
            std::string::npos)
      << clash.err;
  EXPECT_EQ(pdcheck(mm_scene + " -q --units mm").code, 1);  // the same unit is no clash

  // A scene that declares no unit takes --units.
  json bare = read_json(mm_scene);
  bare.erase("units");
  const std::string bare_scene = write_temp("units_none.json", bare.dump());
  const std::string in_report = tmp("units_in.json"), mm_report = tmp("units_mm_report.json");
  ASSERT_EQ(pdcheck(bare_scene + " -q --units in -o " + in_report).code, 1);
  EXPECT_EQ(read_json(in_report)["units"], "in");
  ASSERT_EQ(pdcheck(mm_scene + " -q -o " + mm_report).code, 1);

  for (const std::string option : {"--baseline", "--reuse"}) {
    const CliResult r = pdcheck(mm_scene + " " + option + " " + in_report);
    EXPECT_EQ(r.code, 2) << option << r.err;
    EXPECT_NE(r.err.find("pdcheck: error: " + option + " " + in_report +
                         ": the report is in in, this run in mm"),
              std::string::npos)
        << r.err;
  }
  // Same unit, other settings: the comparison runs, and says what differs.
  const CliResult tol = pdcheck(mm_scene + " --tolerance 0.2 --baseline " + mm_report);
  EXPECT_EQ(tol.code, 1) << tol.err;
  EXPECT_NE(tol.err.find("--baseline " + mm_report +
                         ": written with tolerance 0.1 mm, this run's is 0.2 mm"),
            std::string::npos)
      << tol.err;
  EXPECT_EQ(pdcheck(mm_scene + " --baseline " + mm_report).err.find("written with"),
            std::string::npos);
  const CliResult method = pdcheck(mm_scene + " --method exact --reuse " + mm_report);
  EXPECT_EQ(method.code, 1) << method.err;
  EXPECT_NE(method.err.find("--reuse " + mm_report + ": written with method {"), std::string::npos)
      << method.err;
  EXPECT_NE(method.err.find("no pair was reused"), std::string::npos) << method.err;
  const CliResult same = pdcheck(mm_scene + " --reuse " + mm_report);
  EXPECT_NE(same.err.find("pair(s) reused from"), std::string::npos) << same.err;
  EXPECT_EQ(same.err.find("warning"), std::string::npos) << same.err;

  // pdcheck merge refuses a baseline in another unit too.
  const std::string shard = tmp("units_shard.json");
  ASSERT_EQ(pdcheck(bare_scene + " -q --units in --shard 1/1 -o " + shard).code, 0);
  const CliResult merged = pdcheck("merge " + shard + " -q --baseline " + mm_report);
  EXPECT_EQ(merged.code, 2) << merged.err;
  EXPECT_NE(merged.err.find("the report is in mm, this run in in"), std::string::npos)
      << merged.err;
}
