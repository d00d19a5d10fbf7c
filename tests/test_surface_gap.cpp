// geometry/surface_gap.h: triangle distances against configurations whose
// distance is known exactly, and the surfaces' gap bound on meshes whose
// nearest features are known by construction (long slivers side by side, far
// from the origin).
#include <gtest/gtest.h>

#include "corpus/cad_shapes.h"
#include "geometry/surface_gap.h"

namespace {

using pd::Vec3;
using Tri = std::array<Vec3, 3>;

std::vector<Tri> triangles_of(const pd::Mesh& m) {
  std::vector<Tri> out;
  for (Eigen::Index t = 0; t < m.triangles.cols(); ++t)
    out.push_back({m.vertices.col(m.triangles(0, t)), m.vertices.col(m.triangles(1, t)),
                   m.vertices.col(m.triangles(2, t))});
  return out;
}

TEST(SurfaceGap, TriangleDistanceOfKnownConfigurations) {
  // Parallel and stacked: the gap along z.
  const Tri low{Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 4, 0)};
  EXPECT_DOUBLE_EQ(
      pd::triangle_distance(low, {Vec3(0, 0, 0.25), Vec3(1, 0, 0.25), Vec3(0, 1, 0.25)}), 0.25);
  // Edges crossing at right angles, h apart; no corner is nearest.
  const Tri a{Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, -3)};
  const Tri b{Vec3(0, -1, 0.5), Vec3(0, 1, 0.5), Vec3(0, 0, 3)};
  EXPECT_NEAR(pd::triangle_distance(a, b), 0.5, 1e-15);
  EXPECT_NEAR(pd::triangle_distance(b, a), 0.5, 1e-15);
  // A corner over the other's interior: its height.
  EXPECT_NEAR(pd::triangle_distance(low, {Vec3(1, 1, 0.75), Vec3(1, 1, 5), Vec3(2, 1, 5)}), 0.75,
              1e-15);
  // Beside each other in one plane: the corner-to-edge distance.
  EXPECT_NEAR(pd::triangle_distance(low, {Vec3(5, 0, 0), Vec3(9, 0, 0), Vec3(9, 4, 0)}), 1.0,
              1e-15);
}

// Two upright prisms of 48 sides, vertices on the line of their centres: the
// nearest features are those two vertical edges, `gap` apart; every side is a
// sliver 100 long (a CAD shaft's facets).
TEST(SurfaceGap, TheBoundIsTheGapUpToEnoughFarFromTheOrigin) {
  const double gap = 0.3;
  for (const Vec3& at : {Vec3(0, 0, 0), Vec3(2.5e4, -1.2e4, 3e3)}) {
    const pd::Mesh a = pd::shapes::translated(
        pd::shapes::cylinder(Eigen::Vector2d(0, 0), 5.0, 0.0, 100.0, 48), at);
    const pd::Mesh b = pd::shapes::translated(
        pd::shapes::cylinder(Eigen::Vector2d(10.0 + gap, 0), 5.0, 0.0, 100.0, 48), at);
    const std::vector<Tri> ta = triangles_of(a), tb = triangles_of(b);
    const pd::TriangleTree tree(tb);
    const double got = pd::surface_gap_lower_bound(ta, tb, tree, 1.0);
    EXPECT_LE(got, gap) << "never above the distance";
    EXPECT_GE(got, gap - 1e-9);
    // Sharpened only up to what is asked: a proof that they are 0.2 apart.
    EXPECT_EQ(pd::surface_gap_lower_bound(ta, tb, tree, 0.2), 0.2);
    // Closer than what the caller can use: 0 at once (a valid bound).
    EXPECT_EQ(pd::surface_gap_lower_bound(ta, tb, tree, 1.0, 0.5), 0.0);
    // Touching: 0.
    const pd::Mesh c = pd::shapes::translated(
        pd::shapes::cylinder(Eigen::Vector2d(10.0, 0), 5.0, 0.0, 100.0, 48), at);
    const std::vector<Tri> tc = triangles_of(c);
    EXPECT_LE(pd::surface_gap_lower_bound(ta, tc, pd::TriangleTree(tc), 1.0), 1e-9);
  }
}

}  // namespace
