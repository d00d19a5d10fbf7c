// A pair's old result taken again (reuse.cpp): only under the same settings,
// with both parts unchanged, and never an error; pairs of nonconvex parts too,
// through the binary: their refined result stands, and the run says why the
// others were solved.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "batch/reuse.h"
#include "corpus/cad_shapes.h"
#include "results/fingerprint.h"
#include "shell_run.h"
#include "stl_file.h"

using namespace pd;

namespace {

PriorResults prior_of() {
  PriorResults p;
  p.settings_hash = "s1";
  p.part_hash = {{"frame", "hf"}, {"lid", "hl"}, {"pin", "hp"}};
  PairResult lid;
  lid.status = Status::kInterference;
  lid.depth = 1.5;
  lid.method = "mlsl";
  p.pairs[pair_fingerprint("frame", "lid")] = lid;
  PairResult pin;
  pin.status = Status::kError;
  pin.error = "worker crashed";
  p.pairs[pair_fingerprint("frame", "pin")] = pin;
  return p;
}

}  // namespace

TEST(Reuse, TheSamePairUnderTheSameSettingsIsReused) {
  const PriorResults p = prior_of();
  const auto r = prior_result(p, "s1", 4, "frame", "hf", 7, "lid", "hl");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->a, 4);  // this run's indices
  EXPECT_EQ(r->b, 7);
  EXPECT_TRUE(r->reused);
  EXPECT_EQ(r->status, Status::kInterference);
  EXPECT_EQ(r->depth, 1.5);
  EXPECT_EQ(r->method, "mlsl");
  // The fingerprint does not depend on which part is a.
  EXPECT_TRUE(prior_result(p, "s1", 0, "lid", "hl", 1, "frame", "hf"));
}

TEST(Reuse, AnythingChangedIsSolvedAgain) {
  const PriorResults p = prior_of();
  EXPECT_FALSE(prior_result(p, "s2", 0, "frame", "hf", 1, "lid", "hl"));   // other settings
  EXPECT_FALSE(prior_result(p, "s1", 0, "frame", "hf", 1, "lid", "hX"));   // lid changed
  EXPECT_FALSE(prior_result(p, "s1", 0, "frame", "hX", 1, "lid", "hl"));   // frame changed
  EXPECT_FALSE(prior_result(p, "s1", 0, "frame", "hf", 1, "bolt", "hb"));  // a new part
  EXPECT_FALSE(prior_result(p, "s1", 0, "lid", "hl", 1, "pin", "hp"));     // never solved together
  EXPECT_FALSE(prior_result(p, "s1", 0, "frame", "hf", 1, "pin", "hp"));   // an error: tried again
}

TEST(Reuse, WhyAPairIsSolvedAgainIsSaid) {
  const PriorResults p = prior_of();
  const auto why = [&](const std::string& settings, const std::string& a, const std::string& ha,
                       const std::string& b, const std::string& hb) {
    ReuseMiss m = ReuseMiss::kSettings;
    EXPECT_FALSE(prior_result(p, settings, 0, a, ha, 1, b, hb, &m));
    return std::string(reuse_miss_key(m));
  };
  EXPECT_EQ(why("s2", "frame", "hf", "lid", "hl"), "settings");
  EXPECT_EQ(why("s1", "frame", "hf", "lid", "hX"), "part_changed");
  EXPECT_EQ(why("s1", "frame", "hf", "bolt", "hb"), "part_changed");
  EXPECT_EQ(why("s1", "lid", "hl", "pin", "hp"), "new_pair");
  EXPECT_EQ(why("s1", "frame", "hf", "pin", "hp"), "error");
}

namespace reuse_test {

// Nonconvex parts as float32 STL: a pin in a plate's clearance hole (the hulls
// overlap, the meshes do not), a block pushed 0.3 into an L-bracket's leg (an
// overlap thickness), and a block pushed 0.5 into an L-bracket decomposed
// into pieces (`pieces: decompose`). `shift` moves the first block along x.
std::string nonconvex_scene(const std::string& dir, double shift) {
  using namespace pd::shapes;
  const auto put = [&](const std::string& id, const Mesh& m) {
    pd::test::write_binary_stl(dir + "/" + id + ".stl", m);
    return nlohmann::json{{"id", id}, {"mesh", id + ".stl"}};
  };
  const Vec3 x1(100, 0, 0), x2(200, 0, 0);
  nlohmann::json parts = {
      put("plate", plate_with_hole(40, 6, 5, 16)),
      put("pin", cylinder({0, 0}, 4.5, -5, 15, 16)),
      put("bracket", translated(l_bracket(40, 5, 20), x1)),
      put("block", translated(box(Vec3(4.7 + shift, 6, 2), Vec3(20, 20, 18)), x1)),
      put("bracket2", translated(l_bracket(40, 5, 20), x2)),
      put("block2", translated(box(Vec3(4.5, 6, 2), Vec3(20, 20, 18)), x2))};
  parts[4]["pieces"] = "decompose";
  const std::string scene = dir + "/scene.json";
  std::ofstream(scene) << nlohmann::json{
      {"version", 1},
      {"units", "mm"},
      {"tolerance", 0.1},
      {"parts", parts}}.dump();
  return scene;
}

nlohmann::json without_run_details(nlohmann::json d) {
  d.erase("seconds");
  d.erase("stage_seconds");
  d.erase("scene");
  d["summary"].erase("reuse");
  for (auto& p : d["pairs"]) p.erase("time_ms"), p.erase("reused");
  for (auto& p : d["parts"]) p.erase("decomposition_seconds"), p.erase("source");
  return d;
}

}  // namespace reuse_test

TEST(Reuse, NonconvexPairsAreReusedWhenTheirPartsAndSettingsAreUnchanged) {
  using nlohmann::json;
  const std::string dir = pd_test::scratch_dir("reuse_nonconvex");
  const std::string moved_dir = dir + "/moved";
  std::filesystem::create_directories(moved_dir);
  reuse_test::nonconvex_scene(dir, 0.0);
  reuse_test::nonconvex_scene(moved_dir, 0.1);
  const auto check = [&](const std::string& args) {
    return pd_test::shell(dir, "\"$PDCHECK\" " + args + " --no-cache --jobs 2");
  };
  ASSERT_EQ(check("scene.json -q -o old.json").code, 1);
  const json old = json::parse(pd_test::read_text(dir + "/old.json"));
  long refined = 0;
  for (const json& p : old["pairs"]) refined += p["depth_source"] != "hull";
  ASSERT_GE(refined, 3) << old.dump();  // mesh test, thickness and pieces
  // Nothing changed: every pair is taken, none refined again, the report the same.
  const pd_test::ShellRun same = check("scene.json --reuse old.json -o same.json");
  ASSERT_EQ(same.code, 1) << same.err;
  const json again = json::parse(pd_test::read_text(dir + "/same.json"));
  const long n = again["summary"]["candidate_pairs"];
  for (const json& p : again["pairs"]) EXPECT_TRUE(p.value("reused", false)) << p.dump();
  EXPECT_EQ(again["summary"]["reuse"], json({{"reused", n}, {"solved", json::object()}}));
  EXPECT_NE(same.err.find(std::to_string(n) + " pair(s) reused from old.json"), std::string::npos)
      << same.err;
  EXPECT_EQ(reuse_test::without_run_details(again), reuse_test::without_run_details(old));
  // One block moved: its pair is solved and refined again, the others reused;
  // the report is a full run's.
  ASSERT_EQ(check("moved/scene.json -q -o full.json").code, 1);
  const pd_test::ShellRun moved = check("moved/scene.json --reuse old.json -o moved.json");
  ASSERT_EQ(moved.code, 1) << moved.err;
  const json got = json::parse(pd_test::read_text(dir + "/moved.json"));
  for (const json& p : got["pairs"])
    EXPECT_EQ(p.value("reused", false), p["a"] != "block" && p["b"] != "block") << p.dump();
  EXPECT_EQ(got["summary"]["reuse"], json({{"reused", n - 1}, {"solved", {{"part_changed", 1}}}}));
  EXPECT_NE(moved.err.find("1 solved again: 1 with a changed or new part"), std::string::npos)
      << moved.err;
  EXPECT_EQ(reuse_test::without_run_details(got),
            reuse_test::without_run_details(json::parse(pd_test::read_text(dir + "/full.json"))));
}
