// STEP assemblies through the binary: mechanisms made with Open CASCADE's
// primitives and Booleans (tests/brep_cases.h), written as one assembly file,
// as one file per part and as a part list, every nominal relation known by
// construction; each finding says how it was made sure of.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "brep_cases.h"
#include "cli_support.h"
#include "scene/parts.h"
#include "scene/split_nodes.h"

namespace {

using nlohmann::json;
using pd::Vec3;
using pd::test::pdcheck;
using pd_test::BrepCasePart;
using Kind = pd_test::BrepSolid::Kind;

// Fits of a 4 mm pin in a plate's 4 mm bore, a box sunk 1 mm into a plate, a
// ball buried in a housing, an O-ring in its groove (the same torus cut from
// the shaft: tangent faces), a two-solid clip on a block; each pair apart
// from the others by 100 mm, the whole turned and far from the origin.
std::vector<BrepCasePart> mechanisms() {
  std::vector<BrepCasePart> p = {
      {"plate-exact", {Kind::kPlateWithHole, {20, 20, 5, 4}}},
      {"pin-exact", {Kind::kCylinder, {4, 15}}, Vec3(10, 10, -5)},
      {"plate-press", {Kind::kPlateWithHole, {20, 20, 5, 4}}, Vec3(100, 0, 0)},
      {"pin-press", {Kind::kCylinder, {4.0001, 15}}, Vec3(110, 10, -5)},
      {"plate-clear", {Kind::kPlateWithHole, {20, 20, 5, 4}}, Vec3(200, 0, 0)},
      {"pin-clear", {Kind::kCylinder, {3.9, 15}}, Vec3(210, 10, -5)},
      {"plate-sunk", {Kind::kBox, {30, 30, 5}}, Vec3(300, 0, 0)},
      {"box-sunk", {Kind::kBox, {5, 5, 5}}, Vec3(310, 10, 4)},
      {"housing", {Kind::kBox, {30, 30, 30}}, Vec3(400, 0, 0)},
      {"buried", {Kind::kSphere, {3}}, Vec3(415, 15, 15)},
      {"shaft", {Kind::kShaftWithGroove, {5, 20, 1, 10}}, Vec3(500, 0, 0)},
      {"o-ring", {Kind::kTorus, {5, 1}}, Vec3(500, 0, 10)},
      {"block", {Kind::kBox, {10, 10, 10}}, Vec3(600, 0, 0)},
      {"clip", {Kind::kTwoBoxes, {3, 2, 1}}, Vec3(601, 1, 10)},
  };
  for (BrepCasePart& x : p) {  // the whole assembly turned and moved, as a part of a larger one
    const Eigen::AngleAxisd turn(0.3, Vec3(1, 2, 3).normalized());
    x.at = turn * x.at + Vec3(2e4, -1e4, 3e4);
    x.axis = Vec3(1, 2, 3).normalized();
    x.angle = 0.3;
  }
  return p;
}

// The nominal relation of each pair (by part names), and the exact verdicts
// it allows.
const std::map<std::pair<std::string, std::string>, std::pair<std::string, std::string>> kExpected =
    {
        {{"plate-exact", "pin-exact"}, {"contact", "touching"}},
        {{"plate-press", "pin-press"}, {"contact", "false_positive"}},
        {{"plate-clear", "pin-clear"}, {"clearance", "separated"}},
        {{"plate-sunk", "box-sunk"}, {"interference", "interference"}},
        {{"housing", "buried"}, {"interference", "interference"}},
        {{"shaft", "o-ring"}, {"contact", "touching"}},
        {{"block", "clip"}, {"contact", "touching"}},
};

std::string name_of(const std::string& id) {
  return id.substr(id.find('/') + 1);
}

// Every pair of the report right, each with a decisive exact verdict its
// relation allows.
void expect_relations(const json& report, const std::string& what) {
  size_t seen = 0;
  for (const json& p : report["pairs"]) {
    const std::string a = name_of(p["a"]), b = name_of(p["b"]);
    const auto it = kExpected.find({a, b});
    ASSERT_NE(it, kExpected.end()) << what << ": unexpected pair " << a << " " << b;
    ++seen;
    const auto& [relation, verdict] = it->second;
    const std::string status = p["status"];
    if (relation == "interference")
      EXPECT_EQ(status, "interference") << what << " " << a << " " << b;
    else if (relation == "clearance")
      EXPECT_EQ(status, "separated") << what << " " << a << " " << b;
    else
      EXPECT_TRUE(status == "separated" || status == "false_positive")
          << what << " " << a << " " << b << ": " << status;
    ASSERT_TRUE(p.contains("exact")) << what << " " << a << " " << b;
    // A contact's exact answer may be certified as a false positive (within the
    // tolerance) or found touching on the solids: both are right.
    const std::string got = p["exact"]["verdict"];
    if (relation == "contact")
      EXPECT_TRUE(got == verdict || got == "false_positive" || got == "touching")
          << what << " " << a << " " << b << ": " << p["exact"].dump();
    else
      EXPECT_EQ(got, verdict) << what << " " << a << " " << b << ": " << p["exact"].dump();
    EXPECT_TRUE(p["exact"].contains("by")) << p["exact"].dump();
  }
  EXPECT_EQ(seen, kExpected.size()) << what;
  EXPECT_EQ(report["summary"]["undecided"], 0) << what;
}

json run_json(const std::string& args, const std::string& stdin_text = "") {
  const auto r = pdcheck(args + " --no-cache -q", stdin_text);
  EXPECT_EQ(r.code, 1) << r.err;  // the interferences
  EXPECT_EQ(r.err, "");
  return json::parse(r.out);
}

// Two parts written as one assembly `name`.step, checked with the scene's
// `settings` (JSON members before "parts"): the report, which must exit with
// `code` and hold one pair.
json one_pair_report(const std::string& name, const std::vector<BrepCasePart>& parts,
                     const std::string& settings, int code) {
  const std::string dir = pd_test::process_dir();
  pd_test::write_step_assembly(dir + name + ".step", parts);
  std::ofstream(dir + name + ".json")
      << "{" << settings << R"(, "parts": [{"id": "s", "mesh": ")" << name << R"(.step"}]})";
  const auto r = pdcheck(dir + name + ".json --no-cache -q");
  EXPECT_EQ(r.code, code) << r.err;
  json report = json::parse(r.out);
  EXPECT_EQ(report["pairs"].size(), 1u) << r.out;
  return report;
}

// A plate with a 4 mm bore and a shaft of `radius` through it, grooved (a
// torus cut) 20 mm from the plate.
std::vector<BrepCasePart> plate_and_grooved_shaft(double radius) {
  return {{"plate", {Kind::kPlateWithHole, {20, 20, 5, 4}}},
          {"shaft", {Kind::kShaftWithGroove, {radius, 40, 1.5, 30}}, Vec3(10, 10, -5)}};
}

// A report without what varies from run to run: seconds and milliseconds.
json without_times(json j) {
  if (j.is_object()) {
    for (const char* k : {"seconds", "stage_seconds", "time_ms"}) j.erase(k);
    for (auto& [k, v] : j.items()) v = without_times(v);
  } else if (j.is_array()) {
    for (json& v : j) v = without_times(v);
  }
  return j;
}

double sag_of(const json& report, const std::string& id) {
  for (const json& part : report["parts"])
    if (part["id"] == id) return part["tessellation"]["sag"];
  return 0.0;
}

TEST(StepAssemblies, OneAssemblyFileEveryRelationConfirmed) {
  const std::string dir = pd_test::process_dir();
  pd_test::write_step_assembly(dir + "mechanisms.step", mechanisms());
  std::ofstream(dir + "assembly.json")
      << R"({"units": "mm", "tolerance": 0.01, "parts": [{"id": "m", "mesh": "mechanisms.step"}]})";
  const json report = run_json(dir + "assembly.json");
  ASSERT_EQ(report["parts"].size(), 14u);
  for (const json& part : report["parts"]) {
    EXPECT_EQ(part["tessellation"]["basis"], "bound") << part.dump();
    EXPECT_DOUBLE_EQ(part["tessellation"]["deflection"].get<double>(), 0.0025);
  }
  expect_relations(report, "assembly");
  // One job or three (the products meshed side by side, the leaves hulled
  // by loaders side by side): the same report but for its times.
  const json one = run_json(dir + "assembly.json --jobs 1");
  const json three = run_json(dir + "assembly.json --jobs 3");
  EXPECT_EQ(without_times(three), without_times(one));
  EXPECT_EQ(without_times(report), without_times(one));
}

TEST(StepAssemblies, OneFilePerPartAndAPartList) {
  const std::string dir = pd_test::process_dir();
  std::string list;
  json scene = {{"units", "mm"}, {"tolerance", 0.01}, {"parts", json::array()}};
  for (const BrepCasePart& p : mechanisms()) {
    const std::string file = dir + p.name + ".step";
    pd_test::write_step_part(file, p);
    scene["parts"].push_back({{"id", "x/" + p.name}, {"mesh", p.name + ".step"}});
    list += "x/" + p.name + "\t" + file + "\n";
  }
  std::ofstream(dir + "parts.json") << scene.dump();
  expect_relations(run_json(dir + "parts.json"), "one file per part");
  expect_relations(run_json("- --tolerance 0.01", list), "part list");
}

// A shaft seated at an exact fit in a plate's 4 mm bore, with a groove (a
// torus, whose certified sag is about the deflection, twice the cylinder's)
// 20 mm from the plate: only the faces near the contact widen its bracket, so the fit is
// certified by the bound where the shaft's worst sag alone would not.
TEST(StepAssemblies, AContactIsWidenedOnlyByTheFacesNearIt) {
  // Meshed at the deflection the default would pick for a 0.05 tolerance, and
  // checked against a tighter one: the groove's sag (≈ δ) counts, the
  // cylinder's (≈ δ/2) does not.
  const json report =
      one_pair_report("seat", plate_and_grooved_shaft(4),
                      R"("units": "mm", "tolerance": 0.02, "deflection": 0.0125)", 0);
  ASSERT_EQ(report["pairs"].size(), 1u);
  const json& pair = report["pairs"][0];
  // The shaft's worst sag (its groove's) would not let the bound decide...
  const double hi = pair.contains("depth_bounds") ? pair["depth_bounds"][1].get<double>() : 0.0;
  ASSERT_GT(hi + 2.0 * sag_of(report, "s/shaft"), 0.02) << report.dump();
  // ... its cylinder's does, and no solid is touched.
  EXPECT_EQ(pair["status"], "separated");
  EXPECT_EQ(pair["exact"]["by"], "deflection-bound") << pair.dump();
  EXPECT_EQ(pair["exact"]["verdict"], "false_positive") << pair.dump();
  EXPECT_LE(pair["exact"]["depth_bounds"][1].get<double>(), 0.02);
}

// The same shaft pressed into the bore, 0.008 over it: the meshes overlap,
// and the overlap's deepest points lie in both parts, near the bore; the
// groove, outside the plate, cannot move them.
TEST(StepAssemblies, AnOverlapIsWidenedOnlyByTheFacesInOrNearTheOtherPart) {
  const json report =
      one_pair_report("press", plate_and_grooved_shaft(4.008),
                      R"("units": "mm", "tolerance": 0.03, "deflection": 0.0125)", 0);
  ASSERT_EQ(report["pairs"].size(), 1u);
  const json& pair = report["pairs"][0];
  ASSERT_EQ(pair["status"], "false_positive") << pair.dump();
  const double lo = pair["depth_bounds"][0], hi = pair["depth_bounds"][1];
  EXPECT_GT(lo, 0.0);
  // The groove's sag would not do.
  ASSERT_GT(hi + 2.0 * sag_of(report, "s/shaft"), 0.03) << pair.dump();
  EXPECT_EQ(pair["exact"]["by"], "deflection-bound") << pair.dump();
  EXPECT_EQ(pair["exact"]["verdict"], "false_positive") << pair.dump();
  EXPECT_LE(pair["exact"]["depth_bounds"][1].get<double>(), 0.03);
}

// A ball of radius 3 buried in a block, 7 from every face of it: both convex,
// so the depth is the move that frees the ball, 13 (the mesh's inscribed ball
// comes out by up to its sag less), while the solids' overlap is the ball, 6
// thick. Against a tolerance just below 13 the bound cannot decide, and the
// solids' thickness, a lower bound of the move, neither contradicts the depth
// nor makes it a false positive.
TEST(StepAssemblies, ABuriedBallsThicknessIsNotItsDepth) {
  const json report = one_pair_report(
      "buried",
      {{"block", {Kind::kBox, {20, 20, 20}}}, {"ball", {Kind::kSphere, {3}}, Vec3(10, 10, 10)}},
      R"("units": "mm", "tolerance": 12.95, "deflection": 0.05)", 1);
  ASSERT_EQ(report["pairs"].size(), 1u);
  const json& pair = report["pairs"][0];
  ASSERT_EQ(pair["status"], "interference") << pair.dump();
  ASSERT_GT(pair["depth"].get<double>(), 12.95) << pair.dump();
  ASSERT_LT(pair["depth"].get<double>(), 13.0) << pair.dump();
  EXPECT_NE(pair["exact"]["verdict"], "inconsistent") << pair.dump();
  EXPECT_NE(pair["exact"]["verdict"], "false_positive") << pair.dump();
  if (pair["exact"].contains("depth_bounds")) {
    EXPECT_LE(pair["exact"]["depth_bounds"][0].get<double>(), 13.0) << pair.dump();
    EXPECT_GE(pair["exact"]["depth_bounds"][1].get<double>(), 13.0) << pair.dump();
  }
}

// A post standing in a plate's bore, 0.049 into the plate's hull and nowhere
// near its material: the hulls' depth is within the tolerance, so no pair
// measures the plate's convexity, and a part not known convex does not make
// the hull depth a lower bound: the solids, apart, are not "inconsistent".
TEST(StepAssemblies, AHullDepthOfPartsNotKnownConvexBoundsNothingFromBelow) {
  const json report = one_pair_report("post",
                                      {{"plate", {Kind::kPlateWithHole, {20, 20, 5, 4}}},
                                       {"post", {Kind::kBox, {2, 2, 10}}, Vec3(9, 9, 5 - 0.049)}},
                                      R"("units": "mm", "tolerance": 0.05)", 0);
  ASSERT_EQ(report["pairs"].size(), 1u);
  const json& pair = report["pairs"][0];
  for (const json& part : report["parts"]) EXPECT_FALSE(part.contains("convex")) << part.dump();
  EXPECT_EQ(pair["exact"]["verdict"], "separated") << pair.dump();
  EXPECT_EQ(pair["status"], "separated") << pair.dump();
}

// A STEP file is read (and meshed) once, when it is split: the parts stage
// takes its meshes from there, as a part file's (one leaf, kept whole) too. A
// read in the parts stage would crash its loader: a part error.
TEST(StepAssemblies, AFileIsReadOnceForTheSplitAndTheParts) {
  const std::string dir = pd_test::process_dir();
  pd_test::write_step_assembly(dir + "once.step", {{"a", {Kind::kBox, {10, 10, 10}}},
                                                   {"b", {Kind::kSphere, {3}}, Vec3(20, 0, 0)}});
  pd_test::write_step_part(dir + "part.step", {"c", {Kind::kCylinder, {2, 5}}, Vec3(40, 0, 0)});
  std::ofstream(dir + "once.json") << R"({"units": "mm", "tolerance": 0.05,
      "parts": [{"id": "s", "mesh": "once.step"}, {"id": "p", "mesh": "part.step"}]})";
  pd::SceneSpec scene = pd::load_scene_file(dir + "once.json");
  pd::split_node_parts(scene);
  ASSERT_EQ(scene.parts.size(), 3u);
  const std::vector<pd::Part> parts =
      pd::build_parts(scene, 1, {}, pd::kDefaultLoadTimeout, {}, pd::kAutoLoadMemory,
                      [](const std::string&) { abort(); });
  for (const pd::Part& p : parts) {
    EXPECT_FALSE(p.error) << p.id << ": " << *p.error;
    ASSERT_TRUE(p.brep) << p.id;
    EXPECT_GT(p.vertex_count, 0) << p.id;  // meshed
  }
  // Meshes larger than the run's memory budget are not kept: the split takes
  // the names, the parts stage reads the file again.
  pd::SceneSpec large = pd::load_scene_file(dir + "once.json");
  pd::SplitLoad load;
  load.keep_mb = 1e-6;
  pd::split_node_parts(large, load);
  ASSERT_EQ(large.parts.size(), 3u);
  EXPECT_FALSE(large.brep_reads);
  for (const pd::Part& p : pd::build_parts(large)) EXPECT_FALSE(p.error) << p.id;
}

// With a cache directory a STEP file's read (its meshes, sags and names) is
// kept, so a rerun meshes nothing: no loader reads the file (a read would
// crash it: a part error), and the parts come out as the first time. A
// damaged entry is a miss: the file is read again, and the entry stored anew.
TEST(StepAssemblies, ARerunMeshesNothing) {
  namespace fs = std::filesystem;
  const std::string dir = pd_test::process_dir();
  const std::string cache = dir + "rerun-cache";
  fs::remove_all(cache);
  pd_test::write_step_assembly(dir + "rerun.step", {{"a", {Kind::kBox, {10, 10, 10}}},
                                                    {"b", {Kind::kSphere, {3}}, Vec3(20, 0, 0)}});
  pd_test::write_step_part(dir + "rerun-part.step",
                           {"c", {Kind::kCylinder, {2, 5}}, Vec3(40, 0, 0)});
  std::ofstream(dir + "rerun.json") << R"({"units": "mm", "tolerance": 0.05,
      "parts": [{"id": "s", "mesh": "rerun.step"}, {"id": "p", "mesh": "rerun-part.step"}]})";
  const auto run = [&](const pd::MeshLoadHook& hook) {
    pd::SceneSpec scene = pd::load_scene_file(dir + "rerun.json");
    pd::SplitLoad load;
    load.cache_dir = cache;
    load.before_load = hook;
    pd::split_node_parts(scene, load);
    pd::PartsCache parts_cache;
    parts_cache.dir = cache;
    return pd::build_parts(scene, 1, {}, pd::kDefaultLoadTimeout, parts_cache, pd::kAutoLoadMemory,
                           hook);
  };
  const auto same = [](const std::vector<pd::Part>& x, const std::vector<pd::Part>& y) {
    ASSERT_EQ(x.size(), 3u);
    ASSERT_EQ(y.size(), 3u);
    for (size_t k = 0; k < 3; ++k) {
      EXPECT_FALSE(y[k].error) << y[k].id << ": " << *y[k].error;
      ASSERT_TRUE(x[k].brep && y[k].brep) << x[k].id;
      EXPECT_EQ(x[k].id, y[k].id);
      EXPECT_EQ(x[k].vertex_count, y[k].vertex_count) << x[k].id;
      EXPECT_EQ(x[k].brep->tessellation.sag, y[k].brep->tessellation.sag) << x[k].id;
      EXPECT_EQ(x[k].box.lo, y[k].box.lo) << x[k].id;
      EXPECT_EQ(x[k].box.hi, y[k].box.hi) << x[k].id;
    }
  };
  const std::vector<pd::Part> first = run({});
  for (const pd::Part& p : first) EXPECT_GT(p.vertex_count, 0) << p.id;
  same(first, run([](const std::string&) { abort(); }));
  // Every B-rep read entry damaged: read again, the same parts.
  size_t damaged = 0;
  for (const auto& e : fs::directory_iterator(cache))
    if (e.path().extension() == ".pdb") {
      std::fstream f(e.path(), std::ios::in | std::ios::out | std::ios::binary);
      f.seekp(-3, std::ios::end);
      f.put('\x7f');
      ++damaged;
    }
  EXPECT_EQ(damaged, 2u);  // the assembly's and the part file's
  same(first, run({}));
  same(first, run([](const std::string&) { abort(); }));  // stored whole again
  // Taken from the cache, the split still keeps no meshes past the budget.
  for (const auto& e : fs::directory_iterator(cache))
    if (e.path().extension() == ".pdn") fs::remove(e.path());
  pd::SceneSpec large = pd::load_scene_file(dir + "rerun.json");
  pd::SplitLoad load;
  load.cache_dir = cache;
  load.keep_mb = 1e-6;
  load.before_load = [](const std::string&) { abort(); };
  pd::split_node_parts(large, load);
  ASSERT_EQ(large.parts.size(), 3u);
  EXPECT_FALSE(large.brep_reads);
}

TEST(StepAssemblies, ASurfaceModelIsAPartErrorNamingIt) {
  const std::string dir = pd_test::process_dir();
  pd_test::write_step_assembly(dir + "surface.step",
                               {{"body", {Kind::kBox, {10, 10, 10}}},
                                {"label", {Kind::kBoxShell, {5, 5, 5}}, Vec3(2, 2, 8)}});
  std::ofstream(dir + "surface.json")
      << R"({"units": "mm", "tolerance": 0.05, "parts": [{"id": "s", "mesh": "surface.step"}]})";
  const auto r = pdcheck(dir + "surface.json --no-cache -q");
  EXPECT_EQ(r.code, 3) << r.err;
  const json report = json::parse(r.out);
  ASSERT_EQ(report["parts"].size(), 2u);
  EXPECT_FALSE(report["parts"][0].contains("error") && !report["parts"][0]["error"].is_null());
  EXPECT_NE(
      report["parts"][1]["error"].get<std::string>().find("\"assembly/label\" holds no solid"),
      std::string::npos)
      << report["parts"][1].dump();
}

}  // namespace
