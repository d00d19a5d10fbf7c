// Convexity measured where a pair's verdict turns on it (batch/convexity_on_demand.h):
// which parts are measured, and that a pair's result never depends on the
// other pairs of the run.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "batch/run.h"
#include "corpus/cad_shapes.h"
#include "scene/mesh_store.h"
#include "scene/part_convexity.h"
#include "scene/scene.h"
#include "scratch_dir.h"
#include "stl_file.h"

namespace {

using nlohmann::json;
using namespace pd;
namespace shapes = pd::shapes;

struct Made {
  std::string id;
  Mesh mesh;
  Vec3 at;
};

// Pairs whose hulls interfere, each with a known answer. A pair measures the
// part with more vertices read per hull vertex first (STL files here: a
// convex part reads 4.5-6 per hull vertex, the plate 60):
// - a plate with a hole round a pin that clears it: the plate is measured
//   first and is nonconvex, so the pin is not measured for this pair;
// - the pin against a box it overlaps by 1: the pin is measured, convex, so
//   the box is too;
// - a cylinder in an L bracket's inner corner, inside the bracket's hull, 6
//   away from it: the bracket (6 per hull vertex against 5.8) is nonconvex,
//   the pair separated on the surfaces, the cylinder never measured;
// - two boxes 1 deep into each other: both measured convex, the hull depth
//   theirs; a lone box: never measured.
std::vector<Made> parts() {
  return {
      {"plate", shapes::plate_with_hole(40, 6, 5, 48), Vec3(0, 0, 0)},
      {"pin", shapes::cylinder(shapes::Vec2(0, 0), 4, -5, 15, 16), Vec3(0, 0, 0)},
      {"stop", shapes::box(Vec3(3, -2, 12), Vec3(8, 2, 14)), Vec3(0, 0, 0)},
      {"bracket", shapes::l_bracket(40, 5, 20), Vec3(100, 0, 0)},
      {"roller", shapes::cylinder(shapes::Vec2(15, 15), 4, 2, 18, 32), Vec3(100, 0, 0)},
      {"box_a", shapes::box(Vec3(0, 0, 0), Vec3(10, 10, 10)), Vec3(200, 0, 0)},
      {"box_b", shapes::box(Vec3(9, 0, 0), Vec3(19, 10, 10)), Vec3(200, 0, 0)},
      {"lone", shapes::box(Vec3(0, 0, 0), Vec3(10, 10, 10)), Vec3(300, 0, 0)},
  };
}

json scene_json(const std::string& dir, const json& pairs = nullptr) {
  json list = json::array();
  for (const Made& m : parts()) {
    const std::string file = dir + "/" + m.id + ".stl";
    pd::test::write_binary_stl(file, m.mesh);
    list.push_back(
        {{"id", m.id},
         {"mesh", file},
         {"transform",
          {{1, 0, 0, m.at.x()}, {0, 1, 0, m.at.y()}, {0, 0, 1, m.at.z()}, {0, 0, 0, 1}}}});
  }
  json s = {{"tolerance", 0.1}, {"parts", list}};
  if (!pairs.is_null()) s["pairs"] = pairs;
  return s;
}

RunResult run(const json& scene) {
  const SceneSpec spec = parse_scene_json(scene.dump(), "scene.json", "");
  RunOptions o;
  o.tolerance = 0.1;
  o.quiet = true;
  o.jobs = 2;
  spec.solver.apply(o.solver);
  return run_scene(spec, o);
}

const Part& part(const RunResult& r, const std::string& id) {
  for (const Part& p : r.parts)
    if (p.id == id) return p;
  throw std::runtime_error("no part " + id);
}

const PairResult& pair(const RunResult& r, const std::string& a, const std::string& b) {
  for (const PairResult& p : r.pairs) {
    const std::string &x = r.parts[size_t(p.a)].id, &y = r.parts[size_t(p.b)].id;
    if ((x == a && y == b) || (x == b && y == a)) return p;
  }
  throw std::runtime_error("no pair " + a + " " + b);
}

TEST(ConvexityOnDemand, APairMeasuresItsPartsUntilOneIsNonconvex) {
  const std::string dir = pd_test::scratch_dir("on_demand", "which").string();
  const RunResult r = run(scene_json(dir));
  ASSERT_EQ(r.pairs.size(), 4u);
  EXPECT_EQ(part(r, "plate").convex, false);
  EXPECT_EQ(part(r, "pin").convex, true);  // by its pair with the stop
  EXPECT_EQ(part(r, "stop").convex, true);
  EXPECT_FALSE(part(r, "roller").convex);
  EXPECT_EQ(part(r, "bracket").convex, false);
  EXPECT_EQ(part(r, "box_a").convex, true);
  EXPECT_EQ(part(r, "box_b").convex, true);
  EXPECT_FALSE(part(r, "lone").convex);  // no pair: never measured

  const PairResult& plate_pin = pair(r, "plate", "pin");
  EXPECT_EQ(plate_pin.status, Status::kSeparated);
  EXPECT_EQ(plate_pin.depth_source, "mesh-test");
  EXPECT_EQ(plate_pin.confirmed, true);
  const PairResult& roller = pair(r, "bracket", "roller");
  EXPECT_EQ(roller.status, Status::kSeparated);
  EXPECT_EQ(roller.depth_source, "mesh-test");
  const PairResult& boxes = pair(r, "box_a", "box_b");
  EXPECT_EQ(boxes.status, Status::kInterference);
  EXPECT_EQ(boxes.depth_source, "hull");
  EXPECT_NEAR(boxes.depth, 1.0, 1e-9);  // two convex parts: the hull depth is exact
  EXPECT_EQ(boxes.confirmed, true);
  const PairResult& stop = pair(r, "pin", "stop");
  EXPECT_EQ(stop.status, Status::kInterference);
  EXPECT_NEAR(stop.depth, 1.0, 1e-6);
}

TEST(ConvexityOnDemand, APairsResultDoesNotDependOnTheOtherPairs) {
  // Each pair alone (the scene lists it) against the whole run, where other
  // pairs measure more parts (the pin): every field of the pair the same.
  const std::string dir = pd_test::scratch_dir("on_demand", "alone").string();
  const RunResult all = run(scene_json(dir));
  for (const auto& [a, b] : std::vector<std::pair<std::string, std::string>>{
           {"plate", "pin"}, {"pin", "stop"}, {"bracket", "roller"}, {"box_a", "box_b"}}) {
    const RunResult alone = run(scene_json(dir, json::array({json::array({a, b})})));
    const PairResult &x = pair(all, a, b), &y = pair(alone, a, b);
    EXPECT_EQ(x.status, y.status) << a << " " << b;
    EXPECT_EQ(x.depth, y.depth) << a << " " << b;
    EXPECT_EQ(x.depth_source, y.depth_source) << a << " " << b;
    EXPECT_EQ(x.confirmed, y.confirmed) << a << " " << b;
    EXPECT_EQ(x.hull_depth, y.hull_depth) << a << " " << b;
    EXPECT_EQ(x.depth_bounds, y.depth_bounds) << a << " " << b;
  }
  // The plate's pair alone does not measure the pin (the plate decides it).
  const RunResult alone = run(scene_json(dir, json::array({json::array({"plate", "pin"})})));
  EXPECT_FALSE(part(alone, "pin").convex);
  EXPECT_EQ(part(alone, "plate").convex, false);
}

TEST(ConvexityOnDemand, APairMeasuresItsFirstPartWhateverAnotherPairFound) {
  // Two rods in an L bracket's inner corner, inside its hull and clear of it.
  // A rod's sides are split in twenty (63 vertices read per hull vertex, the
  // bracket 6), so each pair measures its rod first: convex, then the
  // bracket. The second pair to come measures its rod too, though the first
  // has found the bracket nonconvex by then (alone, it would).
  const std::string dir = pd_test::scratch_dir("on_demand", "first_part").string();
  const auto rod = [](const shapes::Vec2& at, double r) {
    std::vector<shapes::Vec2> profile = {{0, 2}};
    for (int k = 0; k <= 20; ++k) profile.push_back({r, 2 + 16.0 * k / 20});
    profile.push_back({0, 18});
    return shapes::translated(shapes::revolution(profile, 16), Vec3(at.x(), at.y(), 0));
  };
  json list = json::array();
  for (const auto& [id, mesh] :
       std::vector<std::pair<std::string, Mesh>>{{"bracket", shapes::l_bracket(40, 5, 20)},
                                                 {"rod_a", rod({15, 15}, 4)},
                                                 {"rod_b", rod({22, 12}, 3)}}) {
    pd::test::write_binary_stl(dir + "/" + id + ".stl", mesh);
    list.push_back({{"id", id}, {"mesh", dir + "/" + id + ".stl"}});
  }
  for (int jobs : {1, 2}) {
    const SceneSpec spec =
        parse_scene_json(json{{"tolerance", 0.1}, {"parts", list}}.dump(), "scene.json", "");
    RunOptions o;
    o.tolerance = 0.1;
    o.quiet = true;
    o.jobs = jobs;
    const RunResult r = run_scene(spec, o);
    EXPECT_EQ(part(r, "bracket").convex, false) << jobs;
    EXPECT_EQ(part(r, "rod_a").convex, true) << jobs;
    EXPECT_EQ(part(r, "rod_b").convex, true) << jobs;
    for (const char* id : {"rod_a", "rod_b"}) {
      EXPECT_EQ(pair(r, "bracket", id).status, Status::kSeparated) << id;
      EXPECT_EQ(pair(r, "bracket", id).depth_source, "mesh-test") << id;
    }
  }
}

TEST(ConvexityOnDemand, EveryInstanceOfAFileGetsTheSameMeasure) {
  // One bracket file placed four ways (a quarter turn far from the origin, an
  // arbitrary turn, in inches): measured in file coordinates from the file's
  // own positions, the answer does not depend on which instance asks.
  const std::string dir = pd_test::scratch_dir("on_demand", "instances").string();
  const std::string file = dir + "/bracket.stl";
  pd::test::write_binary_stl(file, shapes::l_bracket(40, 5, 20));
  const json quarter = {{0, -1, 0, 20000.5}, {1, 0, 0, -15000.25}, {0, 0, 1, 9000}, {0, 0, 0, 1}};
  const json odd = {{0.36, 0.48, -0.8, 20000.5},
                    {-0.8, 0.6, 0, -15000.25},
                    {0.48, 0.64, 0.6, 9000},
                    {0, 0, 0, 1}};
  const json scene = {{"tolerance", 0.1},
                      {"parts",
                       {{{"id", "plain"}, {"mesh", file}},
                        {{"id", "quarter"}, {"mesh", file}, {"transform", quarter}},
                        {{"id", "odd"}, {"mesh", file}, {"transform", odd}},
                        {{"id", "inches"}, {"mesh", file}, {"units", "in"}}}}};
  const SceneSpec spec = parse_scene_json(scene.dump(), "scene.json", "");
  std::vector<Part> parts = build_parts(spec, 2);
  ASSERT_EQ(parts.size(), 4u);
  std::vector<StoredConvexity> c;
  for (Part& p : parts) {
    ASSERT_FALSE(p.error) << *p.error;
    ASSERT_TRUE(convexity_unmeasured(p)) << p.id;
    c.push_back(measure_file_convexity(p, ""));
    set_convexity(p, c.back());
    EXPECT_EQ(p.convex, false) << p.id;
  }
  EXPECT_GT(c[0].concavity, 0.1);
  // A quarter turn stretches nothing: one key (the run measures the file
  // once for both) and the same bits.
  EXPECT_EQ(convexity_key_of(parts[0]), convexity_key_of(parts[1]));
  EXPECT_EQ(c[0].concavity, c[1].concavity);
  EXPECT_EQ(parts[0].surface->concavity, parts[1].surface->concavity);
  // An arbitrary turn's stretch is 1 within rounding: its own key, the same
  // measure.
  EXPECT_DOUBLE_EQ(c[0].concavity, c[2].concavity);
  // In inches the file is measured against its tolerance / 25.4: the same
  // bracket, nonconvex by as much in scene units.
  EXPECT_NE(convexity_key_of(parts[0]), convexity_key_of(parts[3]));
  EXPECT_NEAR(parts[3].surface->concavity, 25.4 * c[0].concavity,
              1e-6 * parts[3].surface->concavity);
}

TEST(ConvexityOnDemand, TheLoadersHullServesTheMeasureToTheBit) {
  // The loader keeps a file's hull and facets beside its surface in the mesh
  // store, so the measure runs no second qhull; without them (a hull from the
  // hull cache has no facets) the measure finds them again the same way.
  const std::string dir = pd_test::scratch_dir("on_demand", "kept_hull").string();
  const std::string file = dir + "/bracket.stl";
  pd::test::write_binary_stl(file, shapes::l_bracket(40, 5, 20));
  const json scene = {{"tolerance", 0.1}, {"parts", {{{"id", "bracket"}, {"mesh", file}}}}};
  const SceneSpec spec = parse_scene_json(scene.dump(), "scene.json", "");
  const std::string cache = dir + "/cache";
  std::vector<Part> parts = build_parts(spec, 1, {}, kDefaultLoadTimeout, PartsCache{cache});
  ASSERT_EQ(parts.size(), 1u);
  ASSERT_FALSE(parts[0].error) << *parts[0].error;
  ASSERT_TRUE(parts[0].surface && parts[0].surface->stored);
  const StoredMesh& stored = *parts[0].surface->stored;
  ASSERT_TRUE(stored.store->get_hull(stored.key)) << "the loader kept the file's hull";
  const StoredConvexity kept = measure_file_convexity(parts[0], "");
  std::filesystem::remove(std::filesystem::path(stored.store->dir()) / (stored.key + ".pdh"));
  ASSERT_FALSE(stored.store->get_hull(stored.key));
  const StoredConvexity found = measure_file_convexity(parts[0], "");
  EXPECT_GT(kept.concavity, 0.1);
  EXPECT_EQ(kept.concavity, found.concavity);
  EXPECT_EQ(kept.closed, found.closed);
}

}  // namespace
