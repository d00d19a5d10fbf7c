// The parts of a scene (parts.cpp): loaded, placed and hulled the same on any
// number of threads, a mesh file read once under many transforms.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>

#include "corpus/cad_shapes.h"
#include "geometry/hull.h"
#include "geometry/mesh_intersect.h"
#include "geometry/solid_distance.h"
#include "scene/mesh_loader.h"
#include "scene/part_convexity.h"
#include "scene/parts.h"
#include "scene/scene.h"
#include "scene/setup_warnings.h"
#include "stl_file.h"

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
      size_t non_rigid = 0, open = 0;
      for (const auto& w : built[k].warnings) {
        non_rigid += setup_warning_kind(w) == std::string(kNonRigidPlacement);
        // A triangle soup: 100 triangles, no edge shared, said for every instance.
        open += w.rfind("open mesh: 300 boundary edges", 0) == 0;
      }
      EXPECT_EQ(bool(non_rigid_placement(spec.transform)), non_rigid == 1) << spec.id;
      EXPECT_EQ(open, 1u) << spec.id;
    }
  }
  std::remove(obj.c_str());
}

TEST(Parts, EachPlacementIsMeasuredAtItsStretchAndReadsBackPlaced) {
  // Two shapes, each written to four files: one placed once, turned and moved
  // far away (rigid); one in inches, turned (a similarity); one under two
  // placements; one stretched along x. Each part is measured where a pair
  // needs it (here: asked directly), its file at its own stretch, and its
  // surface reads back from the mesh store placed as every stage places it.
  // - An L-bracket (legs 10 long, 2 thick): its hull's slanted face is 4 from
  //   the part at its middle, (a - t) / 2. Nonconvex at tolerance 0.1 (its
  //   concavity tolerance is 0.025): the estimate stops above it, never above 4.
  // - A square block with a 0.0005 notch in one side: convex within 0.025 (in
  //   inches too), never measured above the notch's depth (samples this near
  //   its faces count as on them: screen_convexity).
  const std::vector<std::pair<std::string, Mesh>> shapes_made = {
      {"l", shapes::l_bracket(10, 2, 1)},
      {"notch", shapes::prism({{0, 0}, {10, 0}, {10, 10}, {5, 9.9995}, {0, 10}}, 0, 1)}};
  const std::string dir = testing::TempDir() + "kept_" + std::to_string(getpid()) + "_";
  const std::string turn = "0.36,0.48,-0.8,%, -0.8,0.6,0,%, 0.48,0.64,0.6,%, 0,0,0,1";
  const auto placed = [&](const char* x, const char* y, const char* z) {
    std::string t = turn;
    for (const char* v : {x, y, z}) t.replace(t.find('%'), 1, v);
    return "[" + t + "]";
  };
  std::vector<std::string> files;
  std::string parts;
  for (const auto& made : shapes_made) {
    const std::string& shape = made.first;  // a lambda below uses it: no structured binding
    const Mesh& mesh = made.second;
    for (const char* name : {"sole", "inches", "twice", "stretched"}) {
      files.push_back(dir + shape + "_" + name + ".stl");
      pd::test::write_binary_stl(files.back(), mesh);
    }
    const auto part = [&](const std::string& id, const std::string& file, const std::string& rest) {
      parts += R"({"id": ")" + shape + "_" + id + R"(", "mesh": ")" + file + "\", " + rest + "},";
    };
    const size_t f = files.size() - 4;
    part("sole", files[f], R"("transform": )" + placed("20000.5", "-15000.25", "9000"));
    part("inches", files[f + 1], R"("units": "in", "transform": )" + placed("0", "0", "0"));
    part("twice_a", files[f + 2], R"("transform": )" + placed("100", "0", "0"));
    part("twice_b", files[f + 2], R"("transform": )" + placed("0", "100", "0"));
    part("stretched", files[f + 3], R"("transform": [2,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1])");
  }
  parts.pop_back();
  const SceneSpec s =
      parse_scene_json(R"({"tolerance": 0.1, "parts": [)" + parts + "]}", "s.json", "");
  for (int threads : {1, 3}) {
    auto built = build_parts(s, threads);
    ASSERT_EQ(built.size(), 10u);
    for (Part& p : built) {
      ASSERT_FALSE(p.error) << *p.error;
      ASSERT_TRUE(p.surface) << p.id;
      // Measured where a pair needs it (batch/convexity_on_demand.h), not when loaded.
      ASSERT_TRUE(convexity_unmeasured(p)) << p.id;
      measure_convexity(p, "");
      const bool l = p.id[0] == 'l';
      EXPECT_EQ(p.convex, !l) << p.id;
      if (p.id.find("stretched") != std::string::npos) continue;  // lengths not scaled alike
      const double scale = p.id.find("inches") != std::string::npos ? 25.4 : 1.0;
      if (l) {
        EXPECT_GT(p.surface->concavity, 0.025) << p.id;
        EXPECT_LE(p.surface->concavity, 4 * scale * (1 + 1e-12)) << p.id;
      } else {  // float32 holds 9.9995 to about 5e-7
        EXPECT_GE(p.surface->concavity, 0.0) << p.id;
        EXPECT_LE(p.surface->concavity, (0.0005 + 1e-6) * scale) << p.id;
      }
      // The surface is not held: it reads back from the mesh store as the file
      // has it, placed by the arithmetic every stage uses.
      ASSERT_TRUE(p.surface->stored) << p.id;
      EXPECT_FALSE(p.surface->file_mesh) << p.id;
      const auto file = file_mesh_of(*p.surface);
      const auto& made = *std::find_if(shapes_made.begin(), shapes_made.end(), [&](const auto& m) {
        return p.id.rfind(m.first + "_", 0) == 0;
      });
      EXPECT_EQ(file->triangles.cols(), made.second.triangles.cols()) << p.id;
      const Mesh placed = placed_mesh_of(*p.surface);
      EXPECT_EQ(placed.vertices, apply_placement(file->vertices, p.surface->placement)) << p.id;
      Eigen::AlignedBox3d box;
      for (long v = 0; v < placed.vertices.cols(); ++v) box.extend(Vec3(placed.vertices.col(v)));
      if (p.id.find("sole") != std::string::npos) {
        EXPECT_GT(box.min().cwiseAbs().maxCoeff(), 8000) << p.id;
      }
    }
  }
  for (const std::string& f : files) std::remove(f.c_str());
}
