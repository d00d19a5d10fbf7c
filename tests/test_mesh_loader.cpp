// The mesh loader (mesh_loader.cpp): every format read to the same box, glTF
// node transforms, and files that cannot be read named with why. PLY files
// checked and rewritten before assimp reads them: test_ply_check.cpp.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "scene/mesh_loader.h"
#include "scratch_dir.h"

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
