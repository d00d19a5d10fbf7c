// The scene file (scene_json.cpp): errors that name file and JSON path, units
// and transforms, the same scene on any number of parsing threads.
#include <gtest/gtest.h>

#include "scene/json_split.h"
#include "scene/parts.h"
#include "scene/scene.h"

using namespace pd;

namespace {
// The error a scene gives, the same with 1 and 4 parsing threads (or a note
// that says how they differ).
std::string error_of(const std::string& text) {
  std::string what[2];
  for (int t : {0, 1}) try {
      parse_scene_json(text, "s.json", "", std::nullopt, t ? 4 : 1);
    } catch (const SceneError& e) {
      what[t] = e.what();
    }
  return what[0] == what[1] ? what[0] : "threads differ: " + what[0] + " | " + what[1];
}
const std::string kPart = R"({"id": "a", "vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]]})";
}  // namespace

TEST(SceneJson, ErrorsNameFileAndJsonPath) {
  EXPECT_EQ(
      error_of(
          R"({"tolerance": 1, "parts": [{"id": "a", "vertices": [[0,0,0]], "transfrom": []}]})"),
      "s.json: parts[0].transfrom: unknown key (allowed: deflection, group, id, mesh, motion, "
      "pieces, sag, split, tags, transform, units, vertices)");
  EXPECT_EQ(error_of(R"({"tolerance": "1", "parts": []})"),
            "s.json: tolerance: expected a number > 0, \"auto\" or {\"auto\": true, ...}, got "
            "\"1\"");
  EXPECT_EQ(error_of(R"({"tolerance": -1, "parts": []})"), "s.json: tolerance: must be > 0");
  EXPECT_EQ(error_of(R"({"tolerance": 1, "parts": [{"id": "a", "vertices": [[0,0]]}]})"),
            "s.json: parts[0].vertices[0]: expected [x, y, z]");
  EXPECT_EQ(
      error_of(R"({"tolerance": 1, "parts": [{"id": "a", "vertices": [[0,0,0],[1,"2",3]]}]})"),
      "s.json: parts[0].vertices[1][1]: expected a number, got string");
  EXPECT_EQ(error_of(R"({"tolerance": 1, "units": "furlong", "parts": []})"),
            "s.json: units: unknown unit \"furlong\" (use mm, cm, m, in, ft)");
  EXPECT_EQ(error_of(R"({"tolerance": 1, "parts": [)" + kPart + "," + kPart + "]}"),
            "s.json: parts[1] (\"a\"): duplicate part id \"a\"");
  EXPECT_EQ(error_of(R"({"tolerance": 1, "parts": [)" + kPart + R"(], "pairs": [["a", "b"]]})"),
            "s.json: pairs[0]: unknown part id \"b\"");
  EXPECT_NE(error_of(R"({"tolerance": 1, "parts": [{"id": "a", "mesh": "x", "vertices": []}]})")
                .find("exactly one of"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"tolerance": 1, "parts": [)" + kPart.substr(0, kPart.size() - 1) +
                     R"(, "transform": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,1,1]}]})")
                .find("parts[0].transform: the last row"),
            std::string::npos);
}

TEST(SceneJson, BadJsonGivesLineAndColumn) {
  const std::string e = error_of("{\n  \"tolerance\": 1,\n  \"parts\": [,]\n}");
  EXPECT_NE(e.find("s.json: invalid JSON at line 3, column 13"), std::string::npos) << e;
}

// --units names the unit of a scene that declares none; it never reinterprets a
// declared one (issue 25: a mm scene read as inches moved its parts apart).
TEST(SceneJson, CommandLineUnitsNeverReplaceADeclaredOne) {
  const std::string declared = R"({"units": "mm", "tolerance": 0.1, "parts": []})";
  EXPECT_EQ(parse_scene_json(declared, "s.json", "", std::string("mm")).units, "mm");
  try {
    parse_scene_json(declared, "s.json", "", std::string("in"));
    ADD_FAILURE() << "a declared unit was replaced";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "s.json: units: the scene declares \"mm\" but --units says \"in\": a declared unit "
              "is never reinterpreted (drop --units, or change the scene's \"units\")");
  }
  EXPECT_THROW(parse_scene_json_whole(declared, "s.json", "", std::string("in")), SceneError);
  const SceneSpec bare = parse_scene_json(R"({"tolerance": 0.1, "parts": [
      {"id": "a", "units": "mm", "vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]]}]})",
                                          "s.json", "", std::string("in"));
  EXPECT_EQ(bare.units, "in");
  EXPECT_DOUBLE_EQ(bare.parts[0].to_scene_units, 1 / 25.4);  // the part's own unit still holds
}

TEST(SceneJson, UnitsAndTransformsApply) {
  const SceneSpec s = parse_scene_json(R"({"units": "mm", "tolerance": 0.1, "parts": [
      {"id": "a", "units": "cm", "vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]],
       "transform": [[1,0,0,100],[0,1,0,0],[0,0,1,0],[0,0,0,1]]},
      {"id": "b", "units": "in", "vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]],
       "transform": [0,-1,0,0, 1,0,0,0, 0,0,1,0, 0,0,0,1]}]})",
                                       "s.json", "");
  const auto parts = build_parts(s);
  ASSERT_EQ(parts.size(), 2u);
  // cm to mm, then translate by 100 mm: x spans [100, 110].
  EXPECT_DOUBLE_EQ(parts[0].box.lo.x(), 100.0);
  EXPECT_DOUBLE_EQ(parts[0].box.hi.x(), 110.0);
  // inches to mm, then 90 degrees about z: x spans [-25.4, 0], y [0, 25.4].
  EXPECT_DOUBLE_EQ(parts[1].box.lo.x(), -25.4);
  EXPECT_DOUBLE_EQ(parts[1].box.hi.y(), 25.4);
}

TEST(SceneJson, ThreadsDoNotChangeTheScene) {
  const std::string text = R"({"units": "cm", "tolerance": 0.1,
      "checks": {"motion": {"t1": 2, "dt": 0.5}},
      "parts": [
        {"id": "a ]}", "vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], "units": "mm"},
        {"id": "b", "mesh": "m/box.stl", "transform": [1,0,0,5, 0,1,0,0, 0,0,1,0, 0,0,0,1]},
        {"id": "c\"", "vertices": [[0,0,0],[2,0,0],[0,2,0],[0,0,2]],
         "motion": {"angular_velocity": [0,0,1], "about": [1,2,3], "velocity": [1,0,0]}}],
      "pairs": [["a ]}", "b"]], "solver": {"seed": 7}})";
  ASSERT_TRUE(top_level_array(text, "parts"));  // so four threads take the split path
  const SceneSpec one = parse_scene_json(text, "s.json", "base", std::nullopt, 1);
  const SceneSpec four = parse_scene_json(text, "s.json", "base", std::nullopt, 4);
  ASSERT_EQ(one.parts.size(), 3u);
  ASSERT_EQ(four.parts.size(), 3u);
  EXPECT_EQ(one.units, four.units);
  EXPECT_EQ(one.pairs, four.pairs);
  EXPECT_EQ(one.solver.seed, four.solver.seed);
  for (size_t k = 0; k < 3; ++k) {
    const PartSpec &x = one.parts[k], &y = four.parts[k];
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.where, y.where);
    EXPECT_EQ(x.mesh, y.mesh);
    EXPECT_EQ(x.vertices.has_value(), y.vertices.has_value());
    if (x.vertices && y.vertices) {
      EXPECT_EQ(*x.vertices, *y.vertices);
    }
    EXPECT_EQ(x.transform, y.transform);
    EXPECT_EQ(x.to_scene_units, y.to_scene_units);
    EXPECT_EQ(x.motion.has_value(), y.motion.has_value());
    if (x.motion && y.motion) {
      EXPECT_EQ(x.motion->about, y.motion->about);
      EXPECT_EQ(x.motion->velocity, y.motion->velocity);
    }
  }
  EXPECT_EQ(four.parts[2].id, "c\"");
  EXPECT_DOUBLE_EQ(four.parts[0].to_scene_units, 0.1);  // mm in a cm scene
  ASSERT_TRUE(four.parts[2].motion);
  EXPECT_EQ(four.parts[2].motion->about, Vec3(1, 2, 3));
}

namespace {

// The error of a scene with a moving pair that interferes at dt = 1 (b moves
// through a), under the given motion grid; "" when it reads.
std::string grid_error(const std::string& grid) {
  const std::string text = R"({"tolerance": 0.01, "checks": {"motion": {)" + grid + R"(}},
    "parts": [{"id": "a", "vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]]},
              {"id": "b", "motion": {"velocity": [-1,0,0]},
               "vertices": [[3,0,0],[4,0,0],[3,1,0],[3,0,1]]}]})";
  try {
    pd::parse_scene_json(text, "s.json", "");
  } catch (const pd::SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// More than 2^63 grid steps used to cast to long out of range, pass the step
// cap and skip the sweep: the interfering pair was `separated`, exit 0.
TEST(TimeGridLimits, HugeStepCountsAreRefusedNamingTheField) {
  EXPECT_EQ(grid_error(R"("t1": 4, "dt": 1)"), "");
  EXPECT_EQ(grid_error(R"("t1": 4, "dt": 1e-300)"),
            "s.json: checks.motion.dt: gives 4e+300 time steps, more than 1000000: use a larger "
            "dt");
  EXPECT_EQ(grid_error(R"("t1": 9.3e18)"),
            "s.json: checks.motion.dt: gives 9.3e+18 time steps, more than 1000000: use a larger "
            "dt");
  EXPECT_EQ(grid_error(R"("t0": -1e308, "t1": 1e308)"),
            "s.json: checks.motion.t1: t1 - t0 is beyond the double range");
  EXPECT_EQ(grid_error(R"("t1": 999999)"), "");  // 1,000,000 steps: the cap itself
  EXPECT_NE(grid_error(R"("t1": 1000000)").find("more than 1000000"), std::string::npos);
  // Times that cannot differ by dt at their magnitude would repeat one time.
  EXPECT_EQ(grid_error(R"("t0": 1e20, "t1": 1.000000000000002e20)"),
            "s.json: checks.motion.dt: below the resolution of double-precision times at |t| = "
            "1e+20: use a larger dt or shift t0");
}

// solver.grid / solver.gs_local up to 100,000 meant hours for one pair.
TEST(SolverLimits, GridAndGsLocalAreBounded) {
  auto error = [](const std::string& solver) -> std::string {
    try {
      pd::parse_scene_json(R"({"tolerance": 1, "parts": [], "solver": {)" + solver + "}}", "s.json",
                           "");
    } catch (const pd::SceneError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(error(R"("grid": 1000, "gs_local": 10)"), "");
  EXPECT_EQ(error(R"("grid": 1001)"), "s.json: solver.grid: expected an integer from 1 to 1000");
  EXPECT_EQ(error(R"("grid": 100000)"), "s.json: solver.grid: expected an integer from 1 to 1000");
  EXPECT_EQ(error(R"("gs_local": 11)"),
            "s.json: solver.gs_local: expected an integer from 1 to 10");
  EXPECT_EQ(error(R"("samples": 100000)"), "");
}
