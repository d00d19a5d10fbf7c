// Nonconvexity measures (geometry/convexity.h) against values known by construction.
#include <gtest/gtest.h>

#include <cmath>

#include "corpus/cad_shapes.h"
#include "geometry/convexity.h"
#include "geometry/hull.h"
#include "geometry/mesh_intersect.h"

using namespace pd;
using namespace pd::shapes;

namespace {
const Vec3 kFar(20000.0, -3000.0, 500.0);

// The estimate never exceeds the true concavity and misses it by at most its resolution.
void expect_concavity(const Concavity& c, double truth) {
  EXPECT_LE(c.value, truth + 1e-9);
  EXPECT_GE(c.value, truth - c.resolution - 1e-9);
  EXPECT_LT(c.resolution, 0.25 * truth);  // the estimate says something
}
}  // namespace

TEST(Convexity, BoxIsConvex) {
  const Convexity c = measure_convexity(translated(box({0, 0, 0}, {10, 20, 30}), kFar), 1e-6);
  EXPECT_TRUE(c.closed);
  EXPECT_EQ(c.shells, 1);
  EXPECT_NEAR(c.volume, 6000, 1e-7);
  EXPECT_NEAR(c.hull_volume, 6000, 1e-7);
  EXPECT_NEAR(c.hull_area, 2 * (200 + 300 + 600), 1e-7);
  EXPECT_NEAR(c.screen, 0.0, 1e-12);
  EXPECT_LE(c.concavity.value, 1e-9);
  EXPECT_TRUE(c.convex);
}

TEST(Convexity, Float32CylinderFarAwayIsConvexWithinTheTolerance) {
  // float32 at x ≈ 20,000 moves vertices by up to ~0.001: not exactly convex.
  const Mesh cyl = float32(translated(cylinder({0, 0}, 5, 0, 30, 64), kFar));
  const Convexity c = measure_convexity(cyl, 0.01);
  EXPECT_TRUE(c.convex);
  EXPECT_LT(c.concavity.value, 0.004);
  EXPECT_NEAR(c.volume, 64 * 0.5 * 25 * std::sin(2 * M_PI / 64) * 30, 0.5);
}

TEST(Convexity, PlateWithHoleConcavityIsTheHoleInradius) {
  for (int segments : {16, 64}) {
    const Convexity c = measure_convexity(plate_with_hole(40, 6, 5, segments), 0.01);
    EXPECT_TRUE(c.closed);
    EXPECT_FALSE(c.convex);
    expect_concavity(c.concavity, 5 * std::cos(M_PI / segments));
    const double hole = 0.5 * segments * 25 * std::sin(2 * M_PI / segments) * 6;
    EXPECT_NEAR(c.hull_volume - c.volume, hole, 1e-9);
    EXPECT_NEAR(c.screen, hole / c.hull_area, 1e-12);
  }
}

TEST(Convexity, LBracketConcavityIsTheCornerGap) {
  // The hull fills the triangle (5,5)-(40,5)-(5,40); its point farthest from
  // the L is (22.5, 22.5) on the hull's slanted face, 17.5 from both legs.
  const Convexity c = measure_convexity(float32(translated(l_bracket(40, 5, 20), kFar)), 0.01);
  EXPECT_FALSE(c.convex);
  expect_concavity(c.concavity, 17.5);
  EXPECT_NEAR((c.concavity.witness - c.concavity.closest).norm(), c.concavity.value, 1e-9);
}

TEST(Convexity, HollowBoxCavityIsFoundByTheInteriorGrid) {
  // The hull's surface lies on the outer shell; only the cavity's centre is
  // far (4) from material.
  const Convexity c = measure_convexity(hollow_box({0, 0, 0}, {10, 10, 10}, 1), 0.01);
  EXPECT_EQ(c.shells, 2);
  EXPECT_NEAR(c.volume, 1000 - 512, 1e-9);
  EXPECT_FALSE(c.convex);
  expect_concavity(c.concavity, 4.0);
  EXPECT_FALSE(c.shells_convex);  // nested shells are one solid with a void
}

TEST(Convexity, SeparateConvexShellsArePieces) {
  const Mesh two = joined({box({0, 0, 0}, {1, 1, 1}), cylinder({5, 0}, 1, 0, 2, 32)});
  const Convexity c = measure_convexity(two, 0.01);
  EXPECT_EQ(c.shells, 2);
  EXPECT_FALSE(c.convex);
  EXPECT_TRUE(c.shells_convex);
  const std::vector<Mesh> s = mesh_shells(two);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].vertices.cols(), 8);
  EXPECT_EQ(s[1].vertices.cols(), 64);
  // One convex shell and one L: not pieces as they are.
  EXPECT_FALSE(measure_convexity(joined({box({0, 0, 0}, {1, 1, 1}), l_bracket(4, 1, 1)}), 0.01)
                   .shells_convex);
}

TEST(Convexity, OpenMeshHasNoVolume) {
  Mesh open = box({0, 0, 0}, {10, 10, 10});
  open.triangles.conservativeResize(3, 10);
  const Convexity c = measure_convexity(open, 0.01);
  EXPECT_FALSE(c.closed);
  EXPECT_EQ(c.volume, 0.0);
  EXPECT_EQ(c.screen, 0.0);
  // Against the surface: the open side's centre is 5 from the walls.
  expect_concavity(c.concavity, 5.0);
}

TEST(Convexity, MeshVolumeIsTranslationInvariant) {
  const Mesh b = hollow_box({0, 0, 0}, {3, 4, 5}, 0.5);
  EXPECT_NEAR(mesh_volume(translated(b, kFar)), mesh_volume(b), 1e-9);
  EXPECT_NEAR(mesh_volume(b), 60 - 2 * 3 * 4, 1e-12);
}

TEST(Convexity, ScreenStopsOnlyAboveItsThreshold) {
  // The L-bracket's concavity is 17.5: a threshold below it stops the estimate
  // early with a lower bound above the threshold; one above it changes nothing.
  const Mesh l = float32(translated(l_bracket(40, 5, 20), kFar));
  const Convexity full = measure_convexity(l, 0.01);
  const ConvexityScreen early = screen_convexity(l, 0.01, 0.5);
  EXPECT_TRUE(early.closed);
  EXPECT_TRUE(early.concavity.stopped);
  EXPECT_GT(early.concavity.value, 0.5);
  EXPECT_LE(early.concavity.value, full.concavity.value);
  const ConvexityScreen all = screen_convexity(l, 0.01, 100.0);
  EXPECT_FALSE(all.concavity.stopped);
  EXPECT_EQ(all.concavity.value, full.concavity.value);
  // A convex part is never stopped: its estimate stays within the tolerance.
  const ConvexityScreen cyl =
      screen_convexity(float32(translated(cylinder({0, 0}, 5, 0, 30, 64), kFar)), 0.01, 0.01);
  EXPECT_FALSE(cyl.concavity.stopped);
  EXPECT_LE(cyl.concavity.value, 0.01);
}

TEST(Convexity, MeasureStoppedAtTheToleranceKeepsEveryFlag) {
  // decompose_convex stops the whole mesh's estimate at the tolerance: a
  // nonconvex mesh's value is then a lower bound, its flags unchanged.
  const Mesh hollow = hollow_box({0, 0, 0}, {10, 10, 10}, 1);
  const Mesh two = joined({box({0, 0, 0}, {1, 1, 1}), cylinder({5, 0}, 1, 0, 2, 32)});
  const Mesh l = float32(translated(l_bracket(40, 5, 20), kFar));
  for (const Mesh* m : {&hollow, &two, &l}) {
    const Convexity full = measure_convexity(*m, 0.01);
    const Convexity early = measure_convexity(*m, 0.01, 0.01);
    EXPECT_FALSE(full.concavity.stopped);
    EXPECT_TRUE(early.concavity.stopped);
    EXPECT_GT(early.concavity.value, 0.01);
    EXPECT_LE(early.concavity.value, full.concavity.value);
    EXPECT_EQ(early.convex, full.convex);
    EXPECT_EQ(early.shells, full.shells);
    EXPECT_EQ(early.nested_shells, full.nested_shells);
    EXPECT_EQ(early.shells_convex, full.shells_convex);
  }
  // A convex mesh runs to the end: the same value.
  const Mesh cyl = float32(translated(cylinder({0, 0}, 5, 0, 30, 64), kFar));
  const Convexity full = measure_convexity(cyl, 0.01);
  const Convexity early = measure_convexity(cyl, 0.01, 0.01);
  EXPECT_TRUE(early.convex);
  EXPECT_FALSE(early.concavity.stopped);
  EXPECT_EQ(early.concavity.value, full.concavity.value);
}

TEST(Convexity, EstimateOnPreparedHullIsTheSame) {
  // One hull_of_points serves several estimates: each gives what the
  // estimate on the points gives, value and witness.
  const Mesh l = float32(translated(l_bracket(40, 5, 20), kFar));
  const PreparedMesh part(l);
  const HullOfPoints h = hull_of_points(l.vertices);
  EXPECT_TRUE(h.solid());
  for (int samples : {64, 1000}) {
    const Concavity a = hull_concavity(l.vertices, part, 0.01, -1.0, l.vertices, samples);
    const Concavity b = hull_concavity(h, part, 0.01, -1.0, l.vertices, samples);
    EXPECT_EQ(a.value, b.value);
    EXPECT_EQ(a.witness, b.witness);
    EXPECT_EQ(a.resolution, b.resolution);
  }
  // A flat set has no solid hull: value 0 either way.
  const Points flat = (Points(3, 4) << 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0).finished();
  EXPECT_FALSE(hull_of_points(flat).solid());
  EXPECT_EQ(hull_concavity(hull_of_points(flat), part, 0.01, -1.0, flat).value, 0.0);
}

TEST(Convexity, TheScreenFromTheHullsPointsIsTheScreenFromEveryCorner) {
  // The parts stage hands the screen its hull's extreme points; the estimate
  // (value, witness, closedness) is the one built from every corner, on convex
  // and nonconvex float32 parts far from the origin, a UV-sphere-like ball
  // among them (every surface point a hull vertex).
  const Vec3 far(24000.5, -1800.25, 640.0);
  std::vector<Vec2> profile;
  for (int k = 0; k <= 12; ++k)
    profile.emplace_back(4 * std::sin(M_PI * k / 12), -4 * std::cos(M_PI * k / 12));
  for (const Mesh& m : {float32(translated(revolution(profile, 24), far)),
                        float32(translated(cylinder({0, 0}, 3, 0, 40, 64), far)),
                        float32(translated(plate_with_hole(40, 6, 5, 32), far)),
                        float32(translated(l_bracket(30, 4, 10), far))}) {
    for (const double stop : {double(INFINITY), 0.05}) {
      const ConvexityScreen all = screen_convexity(m, 0.01, stop);
      const Points extreme = convex_hull(m.vertices).vertices;
      const ConvexityScreen from_hull = screen_convexity(m, 0.01, stop, &extreme);
      EXPECT_EQ(from_hull.closed, all.closed);
      EXPECT_EQ(from_hull.concavity.value, all.concavity.value);
      EXPECT_EQ(from_hull.concavity.witness, all.concavity.witness);
      EXPECT_EQ(from_hull.concavity.stopped, all.concavity.stopped);
    }
  }
}

TEST(Convexity, TheHullsOwnFacetsGiveItsVolumeAndArea) {
  // A 32-sided prism (radius 5, height 30, side points doubled and interior
  // points added) in float32 far from the origin: convex_hull's facets, taken
  // by hull_of_points without a second qhull run, give the prism's volume and
  // area by construction; every vertex lies on the inner side of every facet.
  const int n = 32;
  const double r = 5, height = 30;
  const Vec3 far(20000.25, -15000.5, 9000);
  Points pts(3, 4 * n + 10);
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n;
    for (int z = 0; z < 2; ++z) {
      const Vec3 v = far + Vec3(r * std::cos(a), r * std::sin(a), z * height);
      pts.col(2 * k + z) = v.cast<float>().cast<double>();
      pts.col(2 * n + 2 * k + z) = pts.col(2 * k + z);  // the same point twice
    }
  }
  for (int k = 0; k < 10; ++k)
    pts.col(4 * n + k) = (far + Vec3(0.1 * k, 0.2, 1 + 2 * k)).cast<float>().cast<double>();
  HullTriangles facets;
  const Hull h = convex_hull(pts, &facets);
  ASSERT_EQ(h.dimension, 3);
  ASSERT_EQ(facets.triangles.size(), facets.normals.size());
  const HullOfPoints made = hull_of_points(h.vertices, facets);
  ASSERT_TRUE(made.solid());
  // float32 moves each corner by up to ~1e-3 at 20,000: relative 1e-4 holds.
  const double base = 0.5 * n * r * r * std::sin(2 * M_PI / n);
  const double side = n * 2 * r * std::sin(M_PI / n) * height;
  EXPECT_NEAR(made.volume, base * height, 1e-4 * base * height);
  EXPECT_NEAR(made.total_area, 2 * base + side, 1e-4 * (2 * base + side));
  for (size_t i = 0; i < made.f.normals.size(); ++i) {
    EXPECT_NEAR(made.f.normals[i].norm(), 1.0, 1e-12);
    for (long v = 0; v < made.centred.cols(); ++v)
      EXPECT_LE(made.f.normals[i].dot(made.centred.col(v)) + made.f.offsets[i], 1e-9 * height)
          << "facet " << i << " vertex " << v;
  }
}
