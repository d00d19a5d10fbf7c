// The parts of a scene (parts.cpp): loaded, placed and hulled the same on any
// number of threads, a mesh file read once under many transforms.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>

#include "geometry/hull.h"
#include "scene/mesh_loader.h"
#include "scene/parts.h"
#include "scene/scene.h"
#include "scene/setup_warnings.h"

using namespace pd;

namespace {
const std::string kFormats = std::string(PDCHECK_SOURCE_DIR) + "/testdata/formats/";
}  // namespace

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
