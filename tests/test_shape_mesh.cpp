// brep/shape_mesh.h: a shape's solids as one welded mesh. Checked through the
// loader (scene/mesh_loader.h's load_brep_meshes) on files made with Open
// CASCADE and on Open CASCADE's own sample parts (Debian's occt-misc).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <map>

#include "brep_cases.h"
#include "scene/mesh_loader.h"
#include "scratch_dir.h"

namespace {

using pd::Mesh;
using pd::Vec3;

struct Closure {
  long odd_edges = 0;
  double volume = 0.0;  ///< signed, from the triangles' orientation
};

Closure closure(const Mesh& m) {
  std::map<std::pair<int, int>, int> count;
  Closure c;
  for (long k = 0; k < m.triangles.cols(); ++k) {
    for (int j = 0; j < 3; ++j) {
      const int a = m.triangles(j, k), b = m.triangles((j + 1) % 3, k);
      ++count[{std::min(a, b), std::max(a, b)}];
    }
    const Vec3 p = m.vertices.col(m.triangles(0, k)), q = m.vertices.col(m.triangles(1, k)),
               r = m.vertices.col(m.triangles(2, k));
    c.volume += p.dot(q.cross(r)) / 6.0;
  }
  for (const auto& [e, n] : count) c.odd_edges += n % 2;
  return c;
}

// Open CASCADE's sample nut and screw: the nut's two circles are one edge
// (TShape) at two locations, which a weld keyed by the TShape alone folded
// into one (the mesh closed, its volume 0.17 mm³). Each mesh encloses its
// solid's volume less the chord sag's slivers, oriented outwards.
TEST(ShapeMesh, EdgesSharingATShapeAtTwoLocationsAreTwoEdges) {
  const std::string dir = "/usr/share/opencascade/data/occ/";
  if (!std::filesystem::exists(dir + "mal_ecrou.brep"))
    GTEST_SKIP() << "Open CASCADE's sample parts are not installed (Debian occt-misc)";
  // Volumes of the solids (BRepGProp): nut, screw, rod.
  const std::pair<const char*, double> parts[] = {
      {"mal_ecrou.brep", 30410.6}, {"mal_vis.brep", 29177.4}, {"mal_tige.brep", 259982.0}};
  for (const auto& [file, volume] : parts) {
    const pd::NodeMeshes m = pd::load_brep_meshes(dir + file, 0.0125, false);
    const Closure c = closure(m.meshes[0]);
    EXPECT_EQ(c.odd_edges, 0) << file;
    EXPECT_LT(c.volume, volume) << file;
    EXPECT_GT(c.volume, volume * 0.998) << file;
  }
}

// A sphere's poles, a torus's and a cylinder's seams, a box's shared corners:
// each solid's mesh closed and outward.
TEST(ShapeMesh, PrimitivesAreClosedAndOutward) {
  using Kind = pd_test::BrepSolid::Kind;
  const std::string path = pd_test::process_dir() + "primitives.step";
  pd_test::write_step_assembly(
      path, {{"ball", {Kind::kSphere, {5.0}}},
             {"ring", {Kind::kTorus, {8.0, 2.0}}, Vec3(30, 0, 0)},
             {"shaft", {Kind::kShaftWithGroove, {5.0, 20.0, 1.0, 8.0}}, Vec3(60, 0, 0)},
             {"plate", {Kind::kPlateWithHole, {20.0, 20.0, 5.0, 4.0}}, Vec3(90, 0, 0)}});
  const double pi = 3.14159265358979323846;
  const double volumes[] = {4.0 / 3.0 * pi * 125.0, 2 * pi * pi * 8.0 * 4.0,
                            pi * 25.0 * 20.0 - pi * 1.0 * pi * 5.0,
                            20.0 * 20.0 * 5.0 - pi * 16.0 * 5.0};
  const pd::NodeMeshes m = pd::load_brep_meshes(path, 0.01, true);
  ASSERT_EQ(m.meshes.size(), 4u);
  for (size_t k = 0; k < 4; ++k) {
    const Closure c = closure(m.meshes[k]);
    EXPECT_EQ(c.odd_edges, 0) << m.nodes[k];
    EXPECT_NEAR(c.volume, volumes[k], 0.01 * volumes[k]) << m.nodes[k];
  }
}

}  // namespace
