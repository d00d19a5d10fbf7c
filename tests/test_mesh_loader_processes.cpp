// Mesh files read in loader processes (scene/mesh_loader.h,
// load_meshes_isolated) on tiny files written to a scratch directory: each
// answer is what load_meshes reads in process (meshes, warnings, node paths),
// in the order asked whatever order the loaders take; a file that cannot be
// read, a loader that crashes and one that hangs past the limit cost that file
// only, named with why.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "scene/mesh_loader.h"
#include "scratch_dir.h"

using namespace pd;

namespace {

const std::string kFormats = std::string(PDCHECK_SOURCE_DIR) + "/testdata/formats/";

// A tetrahedron as ASCII STL, its corners at the origin and on the axes at 2.
const std::string kTetrahedron =
    "solid t\n"
    "facet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0 2 0\nvertex 2 0 0\nendloop\nendfacet\n"
    "facet normal 0 -1 0\nouter loop\nvertex 0 0 0\nvertex 2 0 0\nvertex 0 0 2\nendloop\nendfacet\n"
    "facet normal -1 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 2\nvertex 0 2 0\nendloop\nendfacet\n"
    "facet normal 1 1 1\nouter loop\nvertex 2 0 0\nvertex 0 2 0\nvertex 0 0 2\nendloop\nendfacet\n"
    "endsolid t\n";

// A one-triangle PLY with a free-text header line that load_meshes skips with a warning.
const std::string kPlyWithNote =
    "ply\nformat ascii 1.0\nCreated by hand\nelement vertex 3\nproperty float x\n"
    "property float y\nproperty float z\nelement face 1\nproperty list uchar uint "
    "vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

struct Files {
  std::string dir, tetrahedron, ply, missing;
};

Files write_files(const std::string& test) {
  Files f;
  f.dir = pd_test::scratch_dir("mesh_loader_processes", test).string() + "/";
  f.tetrahedron = f.dir + "tetrahedron.stl";
  f.ply = f.dir + "note.ply";
  f.missing = f.dir + "missing.stl";
  pd_test::write_bytes(f.tetrahedron, kTetrahedron);
  pd_test::write_bytes(f.ply, kPlyWithNote);
  return f;
}

void expect_as_in_process(const LoadedMeshes& got, const std::string& path) {
  SCOPED_TRACE(path);
  ASSERT_FALSE(got.error) << *got.error;
  std::vector<std::string> warnings;
  const std::vector<Mesh> want = load_meshes(path, false, &warnings);
  ASSERT_EQ(got.meshes.size(), want.size());
  for (size_t k = 0; k < want.size(); ++k) {
    EXPECT_EQ(got.meshes[k].vertices, want[k].vertices);
    EXPECT_EQ(got.meshes[k].triangles, want[k].triangles);
  }
  EXPECT_EQ(got.warnings, warnings);
  EXPECT_TRUE(got.nodes.empty());
}

}  // namespace

TEST(MeshLoaderProcesses, EachFileIsReadAsInProcessInTheOrderAsked) {
  const Files f = write_files("order");
  for (int jobs : {1, 2}) {
    // The PLY is the smaller file, read last by the loaders, answered first here.
    const auto got = load_meshes_isolated({{f.ply}, {f.tetrahedron}}, jobs, 0, 0);
    ASSERT_EQ(got.size(), 2u);
    expect_as_in_process(got[0], f.ply);
    expect_as_in_process(got[1], f.tetrahedron);
    ASSERT_EQ(got[0].warnings.size(), 1u);
    EXPECT_NE(got[0].warnings[0].find("unknown line \"Created by hand\""), std::string::npos)
        << got[0].warnings[0];
    ASSERT_EQ(got[1].meshes.size(), 1u);
    const Mesh& t = got[1].meshes[0];
    EXPECT_EQ(t.triangles.cols(), 4);
    EXPECT_EQ(t.vertices.rowwise().minCoeff(), Vec3(0, 0, 0));
    EXPECT_EQ(t.vertices.rowwise().maxCoeff(), Vec3(2, 2, 2));
  }
  EXPECT_TRUE(load_meshes_isolated({}, 1, 0, 0).empty());
}

TEST(MeshLoaderProcesses, NodePathsCrossThePipe) {
  const std::string gltf = kFormats + "box_nodes.gltf";
  const NodeMeshes want = load_node_meshes(gltf);
  ASSERT_EQ(want.meshes.size(), 2u);
  MeshRequest by_node{gltf};
  by_node.by_node = true;
  MeshRequest names = by_node;
  names.node_names_only = true;
  const auto got = load_meshes_isolated({by_node, names}, 1, 0, 0);
  ASSERT_FALSE(got[0].error) << *got[0].error;
  EXPECT_EQ(got[0].nodes, want.nodes);
  ASSERT_EQ(got[0].meshes.size(), 2u);
  EXPECT_EQ(got[0].meshes[1].vertices, want.meshes[1].vertices);
  // Names only: the distinct paths, no meshes.
  ASSERT_FALSE(got[1].error) << *got[1].error;
  EXPECT_TRUE(got[1].meshes.empty());
  EXPECT_EQ(got[1].nodes, want.nodes);  // two nodes, one mesh each
}

TEST(MeshLoaderProcesses, AFileThatCannotBeReadCostsItselfOnly) {
  const Files f = write_files("unreadable");
  const std::string garbage = kFormats + "garbage.stl";
  const auto got = load_meshes_isolated({{f.missing}, {garbage}, {f.tetrahedron}}, 1, 0, 0);
  ASSERT_TRUE(got[0].error);
  EXPECT_NE(got[0].error->find(f.missing), std::string::npos) << *got[0].error;
  EXPECT_NE(got[0].error->find("no such file"), std::string::npos) << *got[0].error;
  EXPECT_TRUE(got[0].meshes.empty());
  ASSERT_TRUE(got[1].error);
  EXPECT_NE(got[1].error->find(garbage), std::string::npos) << *got[1].error;
  expect_as_in_process(got[2], f.tetrahedron);
}

TEST(MeshLoaderProcesses, ACrashedOrHungLoaderCostsItsFileOnly) {
  const Files f = write_files("faults");
  const auto crash =
      load_meshes_isolated({{f.ply}, {f.tetrahedron}}, 1, 0, 0, [&](const std::string& path) {
        if (path == f.ply) std::abort();
      });
  ASSERT_TRUE(crash[0].error);
  EXPECT_EQ(*crash[0].error, "cannot load mesh file " + f.ply +
                                 ": the loader process failed: worker crashed (Aborted)");
  expect_as_in_process(crash[1], f.tetrahedron);
  // A loader stuck on its file is stopped at the limit (0.2 s here).
  const auto hang =
      load_meshes_isolated({{f.tetrahedron}}, 1, 0.2, 0, [](const std::string&) { ::pause(); });
  ASSERT_TRUE(hang[0].error);
  EXPECT_EQ(*hang[0].error, "cannot load mesh file " + f.tetrahedron +
                                ": reading it took longer than the load limit of 0.2 s "
                                "(--load-timeout); the loader was stopped");
}
