// The exact ray-parity inside test against references that need no ray: a box
// with a cavity on a grid of coordinates aligned with its corners (every ray
// there runs along an edge or through a vertex first), a float32 cylinder far
// from the origin (convex: inside is below every face plane), and the segment
// test at touching ends.
#include <gtest/gtest.h>

#include <optional>
#include <random>

#include "corpus/cad_shapes.h"
#include "geometry/ray_parity.h"

namespace pd {
namespace {

using Triangles3 = std::vector<std::array<Vec3, 3>>;

Triangles3 triangles_of(const Mesh& m) {
  Triangles3 t;
  for (long f = 0; f < m.triangles.cols(); ++f)
    t.push_back({m.vertices.col(m.triangles(0, f)), m.vertices.col(m.triangles(1, f)),
                 m.vertices.col(m.triangles(2, f))});
  return t;
}

struct Soup {
  TriangleTree tree;
  Vec3 lo, hi;
  explicit Soup(const Mesh& m)
      : tree(triangles_of(m)),
        lo(m.vertices.rowwise().minCoeff()),
        hi(m.vertices.rowwise().maxCoeff()) {}
  RaySide side(const Vec3& p) const { return ray_parity_side(tree, lo, hi, p); }
};

// Where p lies for the closed box [lo, hi], by comparisons.
RaySide box_side(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  if ((p.array() > lo.array()).all() && (p.array() < hi.array()).all()) return RaySide::kInside;
  if ((p.array() >= lo.array()).all() && (p.array() <= hi.array()).all())
    return RaySide::kOnSurface;
  return RaySide::kOutside;
}

// Where p lies for hollow_box(lo, hi, wall): the box less its open cavity.
RaySide hollow_box_side(const Vec3& p, const Vec3& lo, const Vec3& hi, double wall) {
  const RaySide inner = box_side(p, lo + Vec3::Constant(wall), hi - Vec3::Constant(wall));
  if (inner == RaySide::kInside) return RaySide::kOutside;  // in the void
  return inner == RaySide::kOnSurface ? inner : box_side(p, lo, hi);
}

TEST(RayParity, AHollowBoxOnAGridAlignedWithItsCorners) {
  const Vec3 lo(0, 0, 0), hi(4, 4, 4);
  const double wall = 1;
  const Soup soup(shapes::hollow_box(lo, hi, wall));
  // Corner and wall coordinates, between them, and beyond: rays from these
  // points run along edges and through vertices in every axis direction.
  const std::vector<double> c{-1, 0, 0.5, 1, 2, 3, 3.5, 4, 5};
  int checked = 0;
  for (double x : c)
    for (double y : c)
      for (double z : c) {
        const Vec3 p(x, y, z);
        EXPECT_EQ(soup.side(p), hollow_box_side(p, lo, hi, wall)) << x << " " << y << " " << z;
        ++checked;
      }
  EXPECT_EQ(checked, 729);
}

TEST(RayParity, AFloat32CylinderFarFromTheOrigin) {
  const Vec3 far(48213.5, -20117.25, 3311.0);
  const Mesh m =
      shapes::float32(shapes::translated(shapes::cylinder({0, 0}, 6.0, 0.0, 25.0, 64), far));
  const Soup soup(m);
  const Triangles3 t = triangles_of(m);
  // Convex: strictly inside when below every face plane; decided only with a
  // margin far above the rounding of the plane test.
  const double z0 = m.vertices.row(2).minCoeff(), z1 = m.vertices.row(2).maxCoeff();
  const auto reference = [&](const Vec3& p) -> std::optional<RaySide> {
    double wall = -INFINITY;  // the largest height above a wall face's plane
    for (const auto& f : t) {
      const Vec3 n = (f[1] - f[0]).cross(f[2] - f[0]).normalized();
      if (std::abs(n.z()) < 0.5) wall = std::max(wall, n.dot(p - f[0]));
    }
    const double most = std::max({wall, z0 - p.z(), p.z() - z1});
    if (std::abs(wall) > 1e-6 && (p.z() == z0 || p.z() == z1))  // in a cap's plane
      return wall < 0 ? RaySide::kOnSurface : RaySide::kOutside;
    if (std::abs(most) < 1e-6) return std::nullopt;
    return most < 0 ? RaySide::kInside : RaySide::kOutside;
  };
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-8, 8), h(-2, 27);
  int decided = 0, on_surface = 0;
  for (int k = 0; k < 3000; ++k) {
    Vec3 p = far + Vec3(u(rng), u(rng), h(rng));
    // Two thirds of the points level with a corner, in x and y or in z: their
    // axis rays run along the wall's edges or in the caps' planes.
    const Vec3 v = m.vertices.col(rng() % m.vertices.cols());
    if (k % 3 == 1) p.head<2>() = v.head<2>();
    if (k % 3 == 2) p.z() = v.z();
    std::optional<RaySide> want = reference(p);
    if (k % 3 == 1 && p.z() >= z0 && p.z() <= z1) want = RaySide::kOnSurface;  // a wall edge
    if (!want) continue;
    EXPECT_EQ(soup.side(p), *want) << k;
    ++decided;
    on_surface += *want == RaySide::kOnSurface;
  }
  EXPECT_GT(on_surface, 600);
  EXPECT_GT(decided, 1500);
  // Corners and the midpoints of edges (exact in double for float32 corners).
  for (const auto& f : t) {
    EXPECT_EQ(soup.side(f[0]), RaySide::kOnSurface);
    EXPECT_EQ(soup.side((f[0] + f[1]) / 2), RaySide::kOnSurface);
  }
}

// Several soups in one tree: each side is that soup's alone, by comparisons.
// A bolt exported as two bodies face to face (a head on a shank, sharing the
// plane z = 10) and a hollow block beside the shank, on points aligned with
// their corners.
TEST(RayParity, OneRayTellsEachSoupItsSide) {
  const Vec3 block_lo(-3, -3, 3), block_hi(-1.5, 3, 7);
  const double wall = 0.5;
  const std::vector<std::pair<Vec3, Vec3>> boxes{{Vec3(-1, -1, 0), Vec3(1, 1, 10)},
                                                 {Vec3(-2, -2, 10), Vec3(2, 2, 12)}};
  const std::vector<Mesh> bodies{shapes::box(boxes[0].first, boxes[0].second),
                                 shapes::box(boxes[1].first, boxes[1].second),
                                 shapes::hollow_box(block_lo, block_hi, wall)};
  Triangles3 all;
  std::vector<int> label;
  for (size_t i = 0; i < bodies.size(); ++i)
    for (const auto& t : triangles_of(bodies[i])) all.push_back(t), label.push_back(int(i));
  const TriangleTree tree(all);
  const Vec3 lo(-3, -3, 0), hi(3, 3, 12);
  const std::vector<double> c{-3.5, -3, -2.5, -2, -1, 0, 1, 2, 3},
      z{-1, 0, 3, 3.5, 5, 6.5, 7, 10, 11, 12, 13};
  std::vector<RaySide> sides(bodies.size());
  int inside = 0, on_surface = 0;
  for (double x : c)
    for (double y : c)
      for (double h : z) {
        const Vec3 p(x, y, h);
        ray_parity_sides(tree, label, lo, hi, p, sides.data(), sides.size());
        const RaySide want[3] = {box_side(p, boxes[0].first, boxes[0].second),
                                 box_side(p, boxes[1].first, boxes[1].second),
                                 hollow_box_side(p, block_lo, block_hi, wall)};
        for (size_t i = 0; i < bodies.size(); ++i) {
          EXPECT_EQ(sides[i], want[i]) << x << " " << y << " " << h << " soup " << i;
          inside += want[i] == RaySide::kInside;
          on_surface += want[i] == RaySide::kOnSurface;
        }
      }
  EXPECT_GT(inside, 10);
  EXPECT_GT(on_surface, 50);
}

// One given ray: oblique through a face's diagonal (the edge between its two
// triangles) or along an edge proves nothing; a generic one counts.
TEST(RayParity, ARayThroughAnEdgeDecidesNothing) {
  const Soup soup(shapes::box(Vec3(0, 0, 0), Vec3(4, 4, 4)));
  const auto along = [&](const Vec3& p, const Vec3& d) {
    return ray_parity_along(soup.tree, soup.lo, soup.hi, p, d);
  };
  // Every diagonal of the face x = 4 passes its centre (4, 2, 2).
  EXPECT_EQ(along(Vec3(1, 1, 2), Vec3(3, 1, 0)), std::nullopt);
  EXPECT_EQ(along(Vec3(2, 2, 2), Vec3(1, 0, 0)), std::nullopt);  // along an axis
  EXPECT_EQ(along(Vec3(2, 2, 2), Vec3(1, 1, 0)), std::nullopt);  // to the edge x = y = 4
  EXPECT_EQ(along(Vec3(1, 1, 2), Vec3(3, 1.1, 0.3)), RaySide::kInside);
  EXPECT_EQ(along(Vec3(1, 1, 2), Vec3(0, 1.1, 0)), RaySide::kInside);
  EXPECT_EQ(along(Vec3(1, 1, 4), Vec3(3, 1, 0)), RaySide::kOnSurface);  // on the top face
  EXPECT_EQ(along(Vec3(5, 1, 2), Vec3(-1, 0, 0)), RaySide::kOutside);
}

TEST(RayParity, ASegmentMeetsTheSurfaceWhenItTouchesIt) {
  const Mesh m = shapes::box(Vec3(0, 0, 0), Vec3(2, 2, 2));
  const TriangleTree tree(triangles_of(m));
  const Vec3 in(1, 1, 1);
  EXPECT_FALSE(segment_meets_triangles(tree, in, Vec3(1.5, 0.5, 1.999)));
  EXPECT_TRUE(segment_meets_triangles(tree, in, Vec3(1.5, 0.5, 2)));          // ends on the top
  EXPECT_TRUE(segment_meets_triangles(tree, in, Vec3(3, 1, 1)));              // crosses a side
  EXPECT_TRUE(segment_meets_triangles(tree, Vec3(-1, 0, 0), Vec3(3, 0, 0)));  // along an edge
  EXPECT_FALSE(segment_meets_triangles(tree, Vec3(-1, 0, 0), Vec3(-0.5, 2, 2)));
}

}  // namespace
}  // namespace pd
