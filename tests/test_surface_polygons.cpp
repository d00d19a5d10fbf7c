// Polygons on a part's surface (geometry/surface_polygons.h) and what they save
// hull_concavity: a covered point is within `within` of a polygon; the samples
// they skip never change an estimate above `within` (value and witness).
#include <gtest/gtest.h>

#include "corpus/cad_shapes.h"
#include "geometry/convexity.h"
#include "geometry/mesh_intersect.h"
#include "geometry/surface_polygons.h"

using namespace pd;
using namespace pd::shapes;

TEST(SurfacePolygons, CoverPointsOnTheirPolygonsOnly) {
  // A unit square in z = 0 and a needle triangle in x = 5 (a 1° corner at (5, 0, 0)).
  Points corners(3, 7);
  corners << 0, 1, 1, 0, 5, 5, 5,  //
      0, 0, 1, 1, 0, 10, 10,       //
      0, 0, 0, 0, 0, 0, 0.1745506;
  const double within = 1e-3;
  const SurfacePolygons s(corners, {{0, 4}, {4, 7}}, within);
  EXPECT_TRUE(s.covers(Vec3(0.5, 0.5, 0)));
  EXPECT_TRUE(s.covers(Vec3(0.2, 0.9, 0.4 * within)));
  EXPECT_FALSE(s.covers(Vec3(0.5, 0.5, within)));  // off the plane
  EXPECT_FALSE(s.covers(Vec3(1.0001, 0.5, 0)));    // beyond an edge: no slack
  EXPECT_FALSE(s.covers(Vec3(-0.01, -0.01, 0)));   // beyond a corner
  EXPECT_TRUE(s.covers(Vec3(5, 9, 0.1)));          // inside the needle
  // 0.02 beyond the needle's sharp corner, but within within/2 of both its edges'
  // lines: a slack on the edges would let it in.
  EXPECT_FALSE(s.covers(Vec3(5, -0.02, 0)));
  // A degenerate polygon covers nothing.
  Points line(3, 3);
  line << 0, 1, 2, 0, 0, 0, 0, 0, 0;
  EXPECT_FALSE(SurfacePolygons(line, {{0, 3}}, within).covers(Vec3(1, 0, 0)));
}

TEST(SurfacePolygons, ALongSliverPlacedAskewCoversItsPoints) {
  // A shaft's side facet (60 by 0.3) along the diagonal far from the origin:
  // its box spans some 1,700 grid cells, the sliver itself a few dozen. It is
  // kept, and every point on it is covered; points off it are not.
  const Vec3 far(31000.5, -7200.25, 410.0), along = Vec3(1, 1, 1).normalized() * 60,
                                            across = Vec3(1, -1, 0).normalized() * 0.3;
  Points corners(3, 4);
  corners.col(0) = far;
  corners.col(1) = far + along;
  corners.col(2) = far + along + across;
  corners.col(3) = far + across;
  const double within = 3e-3;
  const SurfacePolygons s(corners, {{0, 4}}, within);
  const Vec3 normal = along.cross(across).normalized();
  for (int i = 0; i <= 100; ++i)
    for (double w : {0.01, 0.5, 0.99}) {
      const Vec3 x = far + (0.001 + i / 100.0 * 0.998) * along + w * across;
      EXPECT_TRUE(s.covers(x)) << i << " " << w;
      EXPECT_FALSE(s.covers(x + within * normal)) << i << " " << w;  // off the plane
      EXPECT_FALSE(s.covers(x + 1.02 * across)) << i << " " << w;    // beside it
    }
}

TEST(SurfacePolygons, SkippedSamplesNeverChangeAnEstimateAboveWithin) {
  const Vec3 far(20000.0, -3000.0, 500.0);
  const std::vector<Mesh> meshes = {
      plate_with_hole(40, 6, 5, 32), float32(translated(l_bracket(40, 5, 20), far)),
      float32(translated(cylinder({0, 0}, 5, 0, 30, 64), far)),
      translated(box({0, 0, 0}, {10, 20, 30}), far), drilled_board(3, 2, 10, 1.6, 0.5, 16)};
  for (size_t k = 0; k < meshes.size(); ++k) {
    const Mesh& m = meshes[k];
    const PreparedMesh part(m);
    const double within = std::max(coordinate_noise(m.vertices), 1e-6);
    const SurfacePolygons faces = triangle_polygons(m, within);
    const Concavity all = hull_concavity(m.vertices, part, 0.01, -1.0, m.vertices);
    const Concavity some = hull_concavity(m.vertices, part, 0.01, -1.0, m.vertices,
                                          kConvexitySamples, INFINITY, &faces);
    EXPECT_LE(some.value, all.value) << k;
    // The plate, the L-bracket and the board are nonconvex far above the noise:
    // there the skipped samples change neither the value nor the witness.
    const bool nonconvex = k == 0 || k == 1 || k == 4;
    EXPECT_EQ(all.value > within, nonconvex) << k << ": " << all.value;
    if (nonconvex) {
      EXPECT_EQ(some.value, all.value) << k;
      EXPECT_EQ(some.witness, all.witness) << k;
    }
    // Every face's centroid is on the part, and covered.
    for (long t = 0; t < m.triangles.cols(); ++t) {
      const Vec3 centroid = (m.vertices.col(m.triangles(0, t)) + m.vertices.col(m.triangles(1, t)) +
                             m.vertices.col(m.triangles(2, t))) /
                            3.0;
      EXPECT_TRUE(faces.covers(centroid)) << k << ": face " << t;
    }
  }
}
