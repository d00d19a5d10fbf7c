// The mesh loader (mesh_loader.cpp): every format read to the same box, glTF
// node transforms, and files that cannot be read named with why. PLY files
// checked and rewritten before assimp reads them: test_ply_check.cpp.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "cli_support.h"
#include "scene/mesh_loader.h"
#include "scratch_dir.h"
#include "zip_archive.h"

using namespace pd;
using pd_test::error_of;

namespace {

const std::string kFormats = std::string(PDCHECK_SOURCE_DIR) + "/testdata/formats/";

}  // namespace

TEST(MeshPaths, WhatIsNotAFileIsNamed) {
  const std::string d = pd_test::scratch_dir("mesh_loader", "paths").string() + "/";
  std::filesystem::create_directories(d + "dir.stl");
  ::unlink((d + "fifo.stl").c_str());
  ASSERT_EQ(::mkfifo((d + "fifo.stl").c_str(), 0600), 0);
  std::filesystem::remove(d + "loop.stl");
  std::filesystem::create_symlink(d + "loop.stl", d + "loop.stl");
  std::filesystem::remove(d + "dangling.stl");
  std::filesystem::create_symlink(d + "nowhere.stl", d + "dangling.stl");
  const std::pair<std::string, const char*> cases[] = {
      {d + "dir.stl", "is a directory"},      {d + "fifo.stl", "is a FIFO"},
      {d + "loop.stl", "symbolic link loop"}, {d + "dangling.stl", "dangling symbolic link"},
      {d + "missing.stl", "no such file"},
  };
  for (const auto& [path, says] : cases) {
    const std::string e = error_of<MeshError>([&, p = path] { load_meshes(p, false); });
    EXPECT_NE(e.find(says), std::string::npos) << e;
    EXPECT_NE(e.find(path), std::string::npos) << e;
  }
  struct stat st {};
  if (::stat("/dev/zero", &st) == 0 && S_ISCHR(st.st_mode)) {  // a device node, as it should be
    const std::string e = error_of<MeshError>([&] { load_meshes("/dev/zero", false); });
    EXPECT_NE(e.find("is a device"), std::string::npos) << e;
  }
  std::filesystem::remove_all(d);
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

// The 3MF OpenSCAD writes (lib3mf: Zip64 size fields in every entry, dated
// 1980-00-00), which assimp's own unzip reads as an empty scene: repacked, it
// loads; a container that is no zip says so.
TEST(MeshLoader, ThreeMfAsOpenScadWritesItLoads) {
  if (!pd::test::have_command("openscad")) GTEST_SKIP() << "openscad is not installed";
  const std::string d = pd_test::scratch_dir("mesh_loader", "3mf").string() + "/";
  std::ofstream(d + "lid.scad") << "translate([5, 0, 0]) cube([10, 20, 2]);\n";
  const auto made = pd::test::shell("openscad -o " + d + "lid.3mf " + d + "lid.scad 2>&1");
  ASSERT_EQ(made.code, 0) << made.out;
  // What makes it hard for assimp: the entries' sizes in Zip64 extra fields.
  const std::string bytes = pd_test::read_text(d + "lid.3mf");
  ASSERT_GE(bytes.size(), 30u);
  EXPECT_EQ(bytes.substr(18, 8), std::string(8, '\xff')) << "no Zip64 sizes in the local header";
  const auto sets = load_mesh_vertices(d + "lid.3mf", false);
  ASSERT_EQ(sets.size(), 1u);
  EXPECT_TRUE(sets[0].rowwise().minCoeff().isApprox(Vec3(5, 0, 0), 1e-6))
      << sets[0].rowwise().minCoeff();
  EXPECT_TRUE(sets[0].rowwise().maxCoeff().isApprox(Vec3(15, 20, 2), 1e-6))
      << sets[0].rowwise().maxCoeff();
  // From memory too (the shard plan's and split parts' path).
  EXPECT_EQ(read_meshes(bytes, ".3mf", false).size(), 1u);
  // Not a zip: the container is named as what failed.
  std::ofstream(d + "broken.3mf") << "<model>not a zip</model>";
  const std::string e = error_of<MeshError>([&] { load_meshes(d + "broken.3mf", false); });
  EXPECT_NE(e.find("broken.3mf: the 3MF container (a zip archive) could not be opened: Not a zip "
                   "archive"),
            std::string::npos)
      << e;
  // A zip without a model: said as such.
  std::ofstream(d + "empty.3mf") << pd::zip_archive({{"readme.txt", "nothing here"}});
  const std::string none = error_of<MeshError>([&] { load_meshes(d + "empty.3mf", false); });
  EXPECT_NE(none.find("the 3MF container opened, but"), std::string::npos) << none;
  std::filesystem::remove_all(d);
}
