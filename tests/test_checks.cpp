// Clearance checks and motion sweeps through a run, against exact values; and
// a static scene pays nothing for them. The sweep alone: test_motion_sweep;
// the signed distance: test_signed_distance.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "batch/run.h"
#include "cube_json.h"
#include "report/report_json.h"

using namespace pd;
using nlohmann::json;

using pd_test::cube_json;

namespace {

json run(const json& scene) {
  const SceneSpec spec = parse_scene_json(scene.dump(), "test.json", ".");
  RunOptions o;
  o.tolerance = *spec.tolerance;
  o.quiet = true;
  spec.solver.apply(o.solver);
  const RunResult r = run_scene(spec, o);
  ReportContext ctx{"test.json", "mm", o.tolerance, o.solver, 0.0, std::nullopt, ""};
  json j = json::parse(report_json(ctx, r).dump());
  j.erase("seconds");
  j.erase("stage_seconds");
  for (auto& p : j["pairs"]) p.erase("time_ms");
  return j;
}

const json* find_pair(const json& report, const std::string& a, const std::string& b) {
  for (const auto& p : report["pairs"])
    if (p["a"] == a && p["b"] == b) return &p;
  return nullptr;
}

}  // namespace

TEST(Checks, StaticScenePaysNothing) {
  // The same pairs, the same solves (counters included), the same report.
  const json base = {
      {"tolerance", 0.1},
      {"parts",
       {cube_json("a", 0), cube_json("b", 0.95), cube_json("c", 1.99, 0.2), cube_json("d", 9)}}};
  json with = base;
  with["checks"] = json::object();
  EXPECT_EQ(run(base), run(with));
  EXPECT_EQ(run(base)["simulated"], json({"interference"}));
  // A time grid but no moving part: the pairs are checked statically, as before.
  json grid = base;
  grid["checks"] = {{"motion", {{"t1", 100}}}};
  json swept = run(grid), plain = run(base);
  EXPECT_EQ(swept["simulated"], json({"interference", "motion"}));
  swept.erase("simulated");
  plain.erase("simulated");
  // The settings hash covers the checks asked for, whatever they find.
  EXPECT_NE(swept["hashes"]["settings"], plain["hashes"]["settings"]);
  swept.erase("hashes");
  plain.erase("hashes");
  EXPECT_EQ(swept, plain);
}

TEST(Checks, ClearanceViolationsAgainstExactDistances) {
  json scene = {
      {"tolerance", 0.1},
      {"parts",
       {cube_json("a", 0), cube_json("b", 4), cube_json("c", 0, 8), cube_json("d", 0, 0, 5.5)}},
      {"checks",
       {{"clearance", {{"min", 5.0}, {"pairs", {{{"pair", {"a", "d"}}, {"min", 2.0}}}}}}}}};
  const json r = run(scene);
  EXPECT_EQ(r["simulated"], json({"interference", "clearance"}));
  const json* ab = find_pair(r, "a", "b");  // 3 apart: violates 5
  ASSERT_TRUE(ab);
  EXPECT_EQ((*ab)["status"], "clearance_violation");
  EXPECT_NEAR((*ab)["clearance"]["distance"].get<double>(), 3.0, 1e-9);
  const json* ac = find_pair(r, "a", "c");  // 7 apart: beyond the inflated broad phase
  EXPECT_FALSE(ac);
  const json* ad = find_pair(r, "a", "d");  // 4.5 apart, its own minimum 2: fine
  ASSERT_TRUE(ad);
  EXPECT_EQ((*ad)["status"], "separated");
  EXPECT_NEAR((*ad)["clearance"]["distance"].get<double>(), 4.5, 1e-9);
  EXPECT_EQ(r["summary"]["clearance_violation"], 1);
  EXPECT_EQ(r["summary"]["exit_code"], 1);
}

TEST(Checks, AClearanceIsViolatedByContactAndOverlapAsByAGap) {
  // Clearance 0.2, tolerance 0.1; unit cubes in pairs 10 apart along x: a gap
  // of 0.1, an exact fit (touching faces), a press fit of 0.05 (within the
  // tolerance), an overlap of 0.5 (beyond it), a gap of 0.3 (the clearance met).
  const double second[] = {1.1, 1.0, 0.95, 0.5, 1.3};
  const char* names[] = {"gap", "fit", "press", "clash", "clear"};
  json parts = json::array();
  for (int k = 0; k < 5; ++k) {
    parts.push_back(cube_json(std::string(names[k]) + "-a", 10.0 * k));
    parts.push_back(cube_json(std::string(names[k]) + "-b", 10.0 * k + second[k]));
  }
  const json plain = run({{"tolerance", 0.1}, {"parts", parts}});
  const json checked =
      run({{"tolerance", 0.1}, {"parts", parts}, {"checks", {{"clearance", {{"min", 0.2}}}}}});
  const auto status = [](const json& r, const std::string& n) {
    const json* p = find_pair(r, n + "-a", n + "-b");
    return p ? (*p)["status"].get<std::string>() : "not checked";
  };
  // Without the check: a touching pair is separated, the press fit a false positive.
  EXPECT_EQ(status(plain, "fit"), "separated");
  EXPECT_EQ(status(plain, "press"), "false_positive");
  EXPECT_EQ(status(checked, "gap"), "clearance_violation");
  EXPECT_EQ(status(checked, "fit"), "clearance_violation");
  EXPECT_EQ(status(checked, "press"), "clearance_violation");
  EXPECT_EQ(status(checked, "clash"), "interference");  // the more severe finding
  EXPECT_EQ(status(checked, "clear"), "not checked");   // farther apart than the clearance: culled
  const json& fit = *find_pair(checked, "fit-a", "fit-b");
  EXPECT_NEAR(fit["clearance"]["distance"].get<double>(), 0.0, 1e-9);
  EXPECT_TRUE(fit.contains("at"));  // a finding says where it is
  const json& press = *find_pair(checked, "press-a", "press-b");
  EXPECT_NEAR(press["depth"].get<double>(), 0.05, 1e-9);
  EXPECT_FALSE(press["clearance"].contains("distance"));
  EXPECT_EQ(press["clearance"]["min"], 0.2);
  EXPECT_EQ(checked["summary"]["clearance_violation"], 3);
  EXPECT_EQ(checked["summary"]["interference"], 1);
  EXPECT_EQ(checked["summary"]["false_positive"], 0);
}

TEST(Checks, MotionSweepAgainstAnalyticValues) {
  // b slides along −x through a at 1 unit/s: s(t) = t − 2 until contact at t = 2,
  // then the overlap 1 − |t − 3| (the x overlap is the smallest way out).
  json scene = {{"tolerance", 0.1},
                {"parts", {cube_json("a", 0), cube_json("b", 3)}},
                {"checks", {{"motion", {{"t0", 0}, {"t1", 4}, {"dt", 0.5}, {"series", true}}}}}};
  scene["parts"][1]["motion"] = {{"velocity", {-1, 0, 0}}};
  const json r = run(scene);
  const json* ab = find_pair(r, "a", "b");
  ASSERT_TRUE(ab);
  const json& m = (*ab)["motion"];
  EXPECT_EQ(m["steps"], 9);
  EXPECT_NEAR(m["max_depth"].get<double>(), 1.0, 1e-9);
  EXPECT_EQ(m["t_max_depth"], 3.0);
  EXPECT_NEAR(m["min_distance"].get<double>(), 0.0, 1e-9);
  ASSERT_EQ(m["series"].size(), 9u);
  for (const auto& p : m["series"]) {
    const double t = p[0], v = p[1];
    const double expected = t < 2 ? t - 2 : 1 - std::abs(t - 3);
    EXPECT_NEAR(v, expected, 1e-9) << "t = " << t;
  }
  EXPECT_EQ((*ab)["status"], "interference");
  EXPECT_EQ(r["simulated"], json({"interference", "motion"}));
}

TEST(Checks, MotionNeedsATimeGrid) {
  json scene = {{"tolerance", 0.1}, {"parts", {cube_json("a", 0), cube_json("b", 3)}}};
  scene["parts"][1]["motion"] = {{"velocity", {-1, 0, 0}}};
  try {
    parse_scene_json(scene.dump(), "s.json", ".");
    FAIL() << "accepted a motion without checks.motion";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("parts[1].motion"), std::string::npos) << e.what();
  }
}
