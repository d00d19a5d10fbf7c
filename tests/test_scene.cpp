// The scene (scene/scene.h) as a caller gets it: a small scene file read from
// a scratch directory (mesh paths from the file's directory, units, transform,
// labels, solver overrides applied on the defaults), standard input read as a
// scene or a part list, and the checks every scene passes: unique ids, known
// pair ids, rules' clearances, empty input, mesh files given as scenes.
#include <gtest/gtest.h>

#include <string>

#include "scene/scene.h"
#include "scratch_dir.h"

using namespace pd;
using pd_test::error_of;

namespace {

using IdPairs = std::vector<std::pair<std::string, std::string>>;

const char* kScene = R"({
  "units": "mm", "tolerance": 0.05,
  "solver": {"method": "exact", "seed": 7},
  "checks": {"clearance": {"min": 0.5}},
  "parts": [
    {"id": "bracket", "mesh": "meshes/bracket.stl", "units": "cm", "pieces": "hull",
     "transform": [[1,0,0,10],[0,1,0,0],[0,0,1,0],[0,0,0,1]],
     "tags": ["bought"], "group": "frame/left"},
    {"id": "pin", "vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]]}
  ],
  "pairs": [["bracket", "pin"]]
})";

PartSpec part(const std::string& id, bool mesh = false) {
  PartSpec p;
  p.id = id;
  p.where = "s.json: parts (" + id + ")";
  if (mesh) p.mesh = id + ".stl";
  return p;
}

SceneSpec scene_of(std::vector<PartSpec> parts) {
  SceneSpec s;
  s.path = "s.json";
  s.parts = std::move(parts);
  return s;
}

}  // namespace

TEST(Scene, ASmallSceneFileReadsIntoItsSpec) {
  const std::string dir = pd_test::scratch_dir("scene", "file").string();
  pd_test::write_bytes(dir + "/scene.json", kScene);
  const SceneSpec s = load_scene_file(dir + "/scene.json");
  EXPECT_EQ(s.path, dir + "/scene.json");
  EXPECT_EQ(s.units, "mm");
  EXPECT_EQ(s.tolerance, 0.05);
  EXPECT_FALSE(s.auto_tolerance);
  EXPECT_FALSE(s.part_list);
  ASSERT_EQ(s.parts.size(), 2u);
  const PartSpec& bracket = s.parts[0];
  EXPECT_EQ(bracket.id, "bracket");
  EXPECT_EQ(bracket.mesh, dir + "/meshes/bracket.stl");  // from the scene file's directory
  EXPECT_EQ(bracket.to_scene_units, 10.0);               // cm in a mm scene
  EXPECT_EQ(bracket.transform(0, 3), 10.0);
  EXPECT_EQ(bracket.pieces, Pieces::kHull);
  EXPECT_EQ(bracket.tags, std::vector<std::string>{"bought"});
  EXPECT_EQ(bracket.group, "frame/left");
  const PartSpec& pin = s.parts[1];
  EXPECT_FALSE(pin.mesh);
  ASSERT_TRUE(pin.vertices);
  EXPECT_EQ(pin.vertices->cols(), 4);
  EXPECT_EQ(place_points(*pin.vertices, pin), *pin.vertices);  // mm, no transform
  EXPECT_EQ(pin.pieces, Pieces::kAuto);
  ASSERT_TRUE(s.pairs);
  EXPECT_EQ(*s.pairs, (IdPairs{{"bracket", "pin"}}));
  ASSERT_TRUE(s.checks.clearance);
  EXPECT_EQ(s.checks.clearance->min, 0.5);
  EXPECT_FALSE(s.checks.motion);
  EXPECT_FALSE(empty_scene_problem(s));
  // The scene's solver fields over the defaults; the rest stay.
  SolverSettings settings;
  s.solver.apply(settings);
  EXPECT_EQ(settings.method, Method::kExact);
  EXPECT_EQ(settings.seed, 7u);
  EXPECT_EQ(settings.samples, SolverSettings{}.samples);
  EXPECT_EQ(settings.tau, SolverSettings{}.tau);
  // --pieces: mesh parts only.
  SceneSpec decompose = s;
  override_pieces(decompose, Pieces::kDecompose);
  EXPECT_EQ(decompose.parts[0].pieces, Pieces::kDecompose);
  EXPECT_EQ(decompose.parts[1].pieces, Pieces::kAuto);
}

TEST(Scene, StandardInputIsASceneOrAPartList) {
  const SceneSpec json = parse_stdin_scene(
      "\n  {\"tolerance\": 1, \"parts\": [{\"id\": \"a\", \"mesh\": \"a.stl\"}]}");
  EXPECT_EQ(json.path, "<stdin>");
  EXPECT_FALSE(json.part_list);
  EXPECT_EQ(json.tolerance, 1.0);
  const SceneSpec list = parse_stdin_scene("# parts\nparts/a.stl\nb\tparts/b.obj\n", "cm");
  EXPECT_TRUE(list.part_list);
  EXPECT_EQ(list.units, "cm");
  ASSERT_EQ(list.parts.size(), 2u);
  EXPECT_EQ(list.parts[0].id, "parts/a.stl");
  EXPECT_EQ(list.parts[1].id, "b");
  EXPECT_EQ(list.parts[1].mesh, "parts/b.obj");
}

TEST(Scene, IdsArePartsOnceAndPairsNameKnownParts) {
  EXPECT_EQ(SceneError("s.json: bad").exit_code(), kExitBadInput);  // a usage error
  EXPECT_EQ(error_of<SceneError>([] {
              validate_scene(scene_of({part("a"), part("b")}));
            }),
            "(no error)");
  EXPECT_EQ(error_of<SceneError>([] {
              validate_scene(scene_of({part("a"), part("b"), part("a")}));
            }),
            "s.json: parts (a): duplicate part id \"a\"");
  SceneSpec s = scene_of({part("a"), part("b")});
  s.pairs = IdPairs{{"a", "c"}};
  EXPECT_EQ(error_of<SceneError>([&] { validate_scene(s); }),
            "s.json: pairs[0]: unknown part id \"c\"");
  s.pairs = IdPairs{{"a", "b"}, {"b", "b"}};
  EXPECT_EQ(error_of<SceneError>([&] { validate_scene(s); }),
            "s.json: pairs[1]: a part paired with itself");
  s.pairs.reset();
  s.checks.clearance = ClearanceCheck{0.5, {{"a", "z", 1.0}}, 0.0};
  EXPECT_EQ(error_of<SceneError>([&] { validate_scene(s); }),
            "s.json: checks.clearance.pairs[0]: unknown part id \"z\"");
  // A part split by its nodes later: ids under it are known.
  SceneSpec split = scene_of({part("asm", true), part("b")});
  split.parts[0].split_nodes = true;
  split.pairs = IdPairs{{"asm/housing/bolt", "b"}};
  EXPECT_EQ(error_of<SceneError>([&] { validate_scene(split); }), "(no error)");
}

TEST(Scene, ARulesClearanceNeedsTheScenesClearanceCheck) {
  Rules rules;
  RuleTest t;
  t.name = "bolts";
  t.clearance = 0.3;
  t.where = "s.json: rules.tests[0]";
  rules.tests.push_back(t);
  PairRule p;
  p.a = "a";
  p.b = "b";
  p.clearance = 0.7;
  p.where = "s.json: rules.pairs[0]";
  rules.pairs.push_back(p);
  SceneSpec s = scene_of({part("a"), part("b")});
  EXPECT_EQ(error_of<SceneError>([&] { attach_rules(s, rules); }),
            "s.json: rules.tests[0]: clearance: a rule's clearance refines the scene's clearance "
            "check: add \"checks\": {\"clearance\": {\"min\": ...}} to the scene");
  EXPECT_FALSE(s.rules);
  s.checks.clearance = ClearanceCheck{0.1, {}, 0.0};
  attach_rules(s, rules);
  ASSERT_TRUE(s.rules);
  EXPECT_EQ(s.rules->tests.size(), 1u);
  EXPECT_EQ(s.checks.clearance->rules_reach, 0.7);  // the broad phase reaches the widest
  // Rules without clearances need no clearance check.
  SceneSpec plain = scene_of({part("a")});
  attach_rules(plain, Rules{});
  EXPECT_TRUE(plain.rules);
}

TEST(Scene, NothingToCheckIsSaid) {
  SceneSpec s = scene_of({});
  EXPECT_EQ(empty_scene_problem(s),
            "s.json: no parts (\"parts\" is empty): nothing to check (--allow-empty accepts an "
            "empty input)");
  s.part_list = true;
  s.path = "<stdin>";
  EXPECT_EQ(empty_scene_problem(s),
            "<stdin>: an empty part list (no mesh path on any line): nothing to check "
            "(--allow-empty accepts an empty input)");
  SceneSpec listed = scene_of({part("a"), part("b")});
  listed.pairs.emplace();
  EXPECT_EQ(empty_scene_problem(listed),
            "s.json: pairs: an empty list: no pair to check (leave \"pairs\" out to check every "
            "pair whose boxes meet; --allow-empty accepts an empty input)");
  listed.pairs->emplace_back("a", "b");
  EXPECT_FALSE(empty_scene_problem(listed));
}

TEST(Scene, AMeshFileGivenAsASceneIsNamedSo) {
  EXPECT_TRUE(looks_like_mesh_file("parts/bracket.STL"));
  EXPECT_TRUE(looks_like_mesh_file("a.glb"));
  EXPECT_FALSE(looks_like_mesh_file("scene.json"));
  EXPECT_FALSE(looks_like_mesh_file("stl"));
  const std::string dir = pd_test::scratch_dir("scene", "mesh").string();
  pd_test::write_bytes(dir + "/part.stl", "solid x\nendsolid x\n");
  const std::string e = error_of<SceneError>([&] { load_scene_file(dir + "/part.stl"); });
  EXPECT_NE(e.find(dir + "/part.stl looks like a mesh file, not a scene"), std::string::npos) << e;
  pd_test::write_bytes(dir + "/scene.txt", "solid x\n");
  EXPECT_EQ(
      error_of<SceneError>([&] { load_scene_file(dir + "/scene.txt"); }).find("looks like a mesh"),
      std::string::npos);
  EXPECT_EQ(error_of<SceneError>([&] { load_scene_file(dir); }),
            dir + ": is a directory, not a scene file");
}
