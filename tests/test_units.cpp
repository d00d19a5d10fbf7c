// Units (units.cpp): a mesh file's unit against the scene's.
#include <gtest/gtest.h>

#include "scene/parts.h"
#include "scene/scene.h"
#include "scene/units.h"

using namespace pd;

namespace {
const std::string kFormats = std::string(PDCHECK_SOURCE_DIR) + "/testdata/formats/";
}  // namespace

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
