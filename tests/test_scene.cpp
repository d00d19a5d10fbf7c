#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "geometry/hull.h"
#include "results/fingerprint.h"
#include "scene/json_split.h"
#include "scene/mesh_loader.h"
#include "scene/parts.h"
#include "scene/scene.h"
#include "scene/setup_warnings.h"
#include "scene/units.h"

using namespace pd;

namespace {
const std::string kFormats = std::string(PDCHECK_SOURCE_DIR) + "/testdata/formats/";

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
      "s.json: parts[0].transfrom: unknown key (allowed: group, id, mesh, motion, pieces, sag, "
      "split, "
      "tags, transform, units, vertices)");
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

TEST(PartList, TabSeparatedIdsAndComments) {
  const SceneSpec s =
      parse_part_list("# parts\nwing\tparts/wing.stl\n\nparts/rib.obj\n", "<stdin>");
  ASSERT_EQ(s.parts.size(), 2u);
  EXPECT_EQ(s.parts[0].id, "wing");
  EXPECT_EQ(*s.parts[0].mesh, "parts/wing.stl");
  EXPECT_EQ(s.parts[1].id, "parts/rib.obj");
  EXPECT_THROW(parse_part_list("a\tx.stl\na\ty.stl\n", "<stdin>"), SceneError);
}

TEST(PartList, IdsAreNormalisedPaths) {
  // `find parts`, `find ./parts`, a doubled slash, a detour and the absolute
  // path give the same ids, so the same fingerprints (and baseline findings).
  const std::string cwd = std::filesystem::current_path().string();
  const std::vector<std::string> spellings = {
      "parts/a.stl\nparts/sub/b.stl\n", "./parts/a.stl\n./parts/sub/b.stl\n",
      "parts//a.stl\nparts/sub//b.stl\n", "x/../parts/a.stl\nparts/./sub/../sub/b.stl\n",
      cwd + "/parts/a.stl\n" + cwd + "//parts/sub/b.stl\n"};
  for (const std::string& list : spellings) {
    const SceneSpec s = parse_part_list(list, "<stdin>");
    ASSERT_EQ(s.parts.size(), 2u) << list;
    EXPECT_EQ(s.parts[0].id, "parts/a.stl") << list;
    EXPECT_EQ(s.parts[1].id, "parts/sub/b.stl") << list;
    EXPECT_EQ(pair_fingerprint(s.parts[0].id, s.parts[1].id),
              pair_fingerprint("parts/a.stl", "parts/sub/b.stl"));
  }
  // The file is read as written; ids that stay as they are.
  const SceneSpec s =
      parse_part_list("./parts/a.stl\n../up.stl\n/elsewhere/c.stl\nn\t./m.stl\n", "<stdin>");
  EXPECT_EQ(*s.parts[0].mesh, "./parts/a.stl");
  EXPECT_EQ(s.parts[1].id, "../up.stl");
  if (cwd.rfind("/elsewhere", 0) != 0) {
    EXPECT_EQ(s.parts[2].id, "/elsewhere/c.stl");
  }
  EXPECT_EQ(s.parts[3].id, "n");  // an id given is kept
  EXPECT_EQ(part_list_id("a/.."), ".");
  // One file listed twice under two spellings is one id twice: refused.
  EXPECT_THROW(parse_part_list("parts/a.stl\n./parts/a.stl\n", "<stdin>"), SceneError);
}

TEST(Units, GltfIsReadInMetres) {
  // box_nodes.gltf: a 2 x 4 x 6 box moved to x in [9, 11], and one scaled by 2
  // to x in [-2, 2]; in metres.
  auto part_box = [](const std::string& scene_units, const std::string& part_units) {
    const SceneSpec s = parse_scene_json(
        "{\"units\": \"" + scene_units + "\", \"tolerance\": 0.1, \"parts\": [{\"id\": \"g\", " +
            part_units + "\"mesh\": \"" + kFormats + "box_nodes.gltf\"}]}",
        "s.json", "");
    const std::vector<Part> parts = build_parts(s);
    EXPECT_FALSE(parts[0].error) << *parts[0].error;
    return parts[0].box;
  };
  const Aabb metres = part_box("m", ""), mm = part_box("mm", "");
  EXPECT_EQ(metres.lo.x(), -2.0);
  EXPECT_EQ(metres.hi.x(), 11.0);
  EXPECT_EQ(mm.lo, 1000.0 * metres.lo);
  EXPECT_EQ(mm.hi, 1000.0 * metres.hi);
  const Aabb inches = part_box("in", "");
  EXPECT_NEAR(inches.hi.x(), 11000.0 / 25.4, 1e-9);
  // A part's explicit units win (a file written in mm against the specification).
  const Aabb said_mm = part_box("mm", "\"units\": \"mm\", ");
  EXPECT_EQ(said_mm.lo, metres.lo);
  EXPECT_EQ(said_mm.hi, metres.hi);
  // Other formats take the scene's unit; a part list's glTF is metres too.
  EXPECT_EQ(mesh_to_scene_units("x/part.stl", "m"), 1.0);
  EXPECT_EQ(mesh_to_scene_units("x/part.GLB", "mm"), 1000.0);
  EXPECT_EQ(mesh_to_scene_units("x/part.gltf", "cm"), 100.0);
  const SceneSpec list = parse_stdin_scene("a.gltf\nb.glb\nc.obj\n", std::string("cm"));
  EXPECT_EQ(list.parts[0].to_scene_units, 100.0);
  EXPECT_EQ(list.parts[1].to_scene_units, 100.0);
  EXPECT_EQ(list.parts[2].to_scene_units, 1.0);
  EXPECT_EQ(parse_stdin_scene("a.gltf\n").parts[0].to_scene_units, 1000.0);
}

TEST(MeshLoader, EveryFormatGivesTheSameBox) {
  for (const char* f :
       {"box_ascii.stl", "box_binary.stl", "box.obj", "box_ascii.ply", "box_binary.ply"}) {
    const auto sets = load_mesh_vertices(kFormats + f, false);
    ASSERT_EQ(sets.size(), 1u) << f;
    EXPECT_EQ(sets[0].rowwise().minCoeff(), Vec3(-1, -2, -3)) << f;
    EXPECT_EQ(sets[0].rowwise().maxCoeff(), Vec3(1, 2, 3)) << f;
  }
}

TEST(MeshLoader, GltfNodeTransformsCompose) {
  const auto sets = load_mesh_vertices(kFormats + "box_nodes.gltf", true);
  ASSERT_EQ(sets.size(), 2u);
  // translated by (10, 0, 0)
  EXPECT_TRUE(sets[0].rowwise().minCoeff().isApprox(Vec3(9, -2, -3), 1e-6));
  // scaled by 2, rotated 90 degrees about x ((y, z) -> (-z, y)), then moved by (0, 20, 0)
  EXPECT_TRUE(sets[1].rowwise().minCoeff().isApprox(Vec3(-2, 14, -4), 1e-6))
      << sets[1].rowwise().minCoeff();
  EXPECT_TRUE(sets[1].rowwise().maxCoeff().isApprox(Vec3(2, 26, 4), 1e-6))
      << sets[1].rowwise().maxCoeff();
}

TEST(MeshLoader, UnusableFilesSayWhy) {
  for (const char* f : {"missing.stl", "garbage.stl", "empty.obj"}) {
    try {
      load_mesh_vertices(kFormats + f, false);
      ADD_FAILURE() << f << " loaded";
    } catch (const MeshError& e) {
      EXPECT_NE(std::string(e.what()).find(f), std::string::npos) << e.what();
    }
  }
}

TEST(Parts, ThreadsDoNotChangeTheParts) {
  // Mesh files in every format (some repeated under one transform, so cached;
  // some broken), and inline parts, flat and solid: hulled on 1 and 4 threads.
  std::string parts;
  const char* files[] = {"box_ascii.stl",  "box_binary.stl", "box.obj",     "box_ascii.ply",
                         "box_binary.ply", "box_nodes.gltf", "garbage.stl", "missing.stl"};
  for (int k = 0; k < 40; ++k) {
    const std::string id = "\"p" + std::to_string(k) + "\"";
    if (k % 3 == 2) {
      parts += "{\"id\": " + id + ", \"vertices\": [[0,0,0],[1,0,0],[0,1,0],[0,0," +
               std::to_string(k % 2) + "],[0.2,0.2,0.1]]},";
    } else {
      parts += "{\"id\": " + id + ", \"mesh\": \"" + kFormats + files[k % 8] +
               "\", \"transform\": [1,0,0," + std::to_string(k % 4) +
               ", 0,1,0,0, 0,0,1,0, 0,0,0,1]},";
    }
  }
  parts.pop_back();
  const SceneSpec s =
      parse_scene_json("{\"tolerance\": 0.1, \"parts\": [" + parts + "]}", "s.json", "");
  const auto one = build_parts(s, 1), four = build_parts(s, 4);
  ASSERT_EQ(one.size(), 40u);
  ASSERT_EQ(four.size(), 40u);
  int broken = 0;
  for (size_t k = 0; k < one.size(); ++k) {
    EXPECT_EQ(one[k].id, four[k].id);
    EXPECT_EQ(one[k].source, four[k].source);
    EXPECT_EQ(one[k].error, four[k].error) << one[k].id;
    EXPECT_EQ(one[k].warnings, four[k].warnings) << one[k].id;
    ASSERT_EQ(one[k].pieces.size(), four[k].pieces.size()) << one[k].id;
    for (size_t p = 0; p < one[k].pieces.size(); ++p)
      EXPECT_EQ(one[k].pieces[p].vertices, four[k].pieces[p].vertices) << one[k].id;
    EXPECT_EQ(one[k].box.lo, four[k].box.lo);
    EXPECT_EQ(one[k].box.hi, four[k].box.hi);
    broken += one[k].error.has_value();
  }
  EXPECT_GT(broken, 0);  // the broken files stayed errors, named per part
}

TEST(JsonSplit, ElementsOfTheTopLevelArray) {
  const std::string text =
      R"( { "a": {"parts": [1]}, "s": "]\"[", "parts" : [ {"id": "x]\"}"} ,[1,[2]], "q", 3.5e2 ,)"
      R"(null ] , "z": [] } )";
  const auto span = top_level_array(text, "parts");
  ASSERT_TRUE(span);
  std::vector<std::string> got;
  for (const auto& [b, e] : span->elements) got.push_back(text.substr(b, e - b));
  EXPECT_EQ(got,
            (std::vector<std::string>{R"({"id": "x]\"}"})", "[1,[2]]", "\"q\"", "3.5e2", "null"}));
  EXPECT_EQ(text[span->begin], '[');
  EXPECT_EQ(text[span->end - 1], ']');
  EXPECT_TRUE(top_level_array(R"({"parts": []})", "parts")->elements.empty());
  // Not split: the whole-text parse decides (and reports any error).
  for (const char* bad : {R"([1, 2])", R"({"parts": 3})", R"({"parts": [1], "parts": [2]})",
                          R"({"parts": [1, 2)", R"({"parts": [1 2]})", R"({"parts": [1]} x)",
                          R"({"parts": ["1]})", R"({"other": [1]})", R"({})", ""})
    EXPECT_FALSE(top_level_array(bad, "parts")) << bad;
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

TEST(Parts, OneMeshFileUnderManyTransforms) {
  // A file with interior points, placed under several units and transforms:
  // each instance's hull is the hull of the placed file (the file is read and
  // reduced to its hull once, then each instance hulls the placed reduction).
  const std::string obj = testing::TempDir() + "cloud_" + std::to_string(getpid()) + ".obj";
  {
    std::ofstream f(obj);
    f.precision(17);
    unsigned seed = 7;
    auto uniform = [&] { return (seed = seed * 1103515245u + 12345u) / 4294967296.0 * 2 - 1; };
    for (int k = 0; k < 300; ++k)
      f << "v " << uniform() << " " << uniform() << " " << uniform() << "\n";
    for (int k = 1; k + 2 <= 300; k += 3) f << "f " << k << " " << k + 1 << " " << k + 2 << "\n";
  }
  const std::string parts =
      R"([
      {"id": "a", "mesh": ")" +
      obj + R"("},
      {"id": "b", "mesh": ")" +
      obj + R"(", "units": "in", "transform": [0,-2,0,5, 1,0,0,-3, 0,0,0.5,1e4, 0,0,0,1]},
      {"id": "c", "mesh": ")" +
      obj + R"(", "transform": [1,0.5,0,0, 0,-1,0,0, 0,0,3,0, 0,0,0,1]},
      {"id": "d", "mesh": ")" +
      obj + R"(", "units": "in", "transform": [0,-2,0,5, 1,0,0,-3, 0,0,0.5,1e4, 0,0,0,1]}])";
  const SceneSpec s =
      parse_scene_json(R"({"tolerance": 0.1, "parts": )" + parts + "}", "s.json", "");
  const auto raw = load_mesh_vertices(obj, false);
  ASSERT_EQ(raw.size(), 1u);
  for (int threads : {1, 3}) {
    const auto built = build_parts(s, threads);
    ASSERT_EQ(built.size(), 4u);
    for (size_t k = 0; k < built.size(); ++k) {
      const PartSpec& spec = s.parts[k];
      const Points placed =
          (spec.transform.topLeftCorner<3, 3>() * (raw[0] * spec.to_scene_units)).colwise() +
          Vec3(spec.transform.topRightCorner<3, 1>());
      const Hull direct = convex_hull(placed);
      ASSERT_FALSE(built[k].error) << *built[k].error;
      EXPECT_EQ(built[k].vertex_count, raw[0].cols());
      ASSERT_EQ(built[k].pieces.size(), 1u);
      EXPECT_LT(direct.vertices.cols(), raw[0].cols());  // interior points were dropped
      EXPECT_EQ(built[k].pieces[0].vertices, direct.vertices) << spec.id;
      EXPECT_EQ(built[k].pieces[0].dimension, direct.dimension) << spec.id;
      // The hull's own warnings; these transforms scale, and say so (a set-up warning).
      std::vector<std::string> hull_warnings;
      for (const auto& w : built[k].warnings)
        if (!setup_warning_kind(w)) hull_warnings.push_back(w);
      EXPECT_EQ(hull_warnings, direct.warnings) << spec.id;
      EXPECT_EQ(bool(non_rigid_placement(spec.transform)),
                built[k].warnings.size() == hull_warnings.size() + 1)
          << spec.id;
    }
  }
  std::remove(obj.c_str());
}
