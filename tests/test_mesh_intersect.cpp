// Exact mesh tests (geometry/mesh_intersect.h) on parts whose relation is known
// by construction.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "corpus/cad_shapes.h"
#include "geometry/mesh_intersect.h"
#include "random_rotation.h"
#include "solve/exact.h"

using namespace pd;
using namespace pd::shapes;

namespace {

const Vec3 kFar(20000.0, -3000.0, 500.0);  // where CAD exports put parts

// A plate with a bolt hole (radius 5, `segments`) and a bolt of radius r
// through it, both as float32 meshes at `offset`.
struct BoltCase {
  Mesh plate, bolt;
};
BoltCase bolt_case(double r, int segments, const Vec3& offset, bool round) {
  BoltCase c{plate_with_hole(40, 6, 5.0, segments), cylinder({0, 0}, r, -10, 16, segments)};
  c.plate = translated(c.plate, offset);
  c.bolt = translated(c.bolt, offset);
  if (round) c.plate = float32(c.plate), c.bolt = float32(c.bolt);
  return c;
}

Points verts(const Mesh& m) {
  return m.vertices;
}

}  // namespace

TEST(MeshIntersect, Boxes) {
  const Mesh a = box({0, 0, 0}, {10, 10, 10});
  EXPECT_TRUE(meshes_intersect(a, box({9, 2, 2}, {20, 8, 8})));        // overlap
  EXPECT_FALSE(meshes_intersect(a, box({10.001, 2, 2}, {20, 8, 8})));  // apart
  EXPECT_TRUE(meshes_intersect(a, box({10, 2, 2}, {20, 8, 8})));       // face contact
  EXPECT_TRUE(meshes_intersect(a, box({10, 10, 10}, {20, 20, 20})));   // corner contact
  EXPECT_FALSE(meshes_intersect(a, box({10, 10, 10.5}, {20, 20, 20})));
}

TEST(MeshIntersect, ContainmentBothWays) {
  const Mesh big = box({0, 0, 0}, {10, 10, 10}), small = box({4, 4, 4}, {6, 6, 6});
  EXPECT_TRUE(meshes_intersect(big, small));
  EXPECT_TRUE(meshes_intersect(small, big));
  // A second shell of the small part outside: still contained in part.
  const Mesh two = joined({small, box({20, 0, 0}, {21, 1, 1})});
  EXPECT_TRUE(meshes_intersect(big, two));
  EXPECT_TRUE(meshes_intersect(two, big));
  EXPECT_EQ(PreparedMesh(two).shells(), 2);
}

TEST(MeshIntersect, BoltInHoleClearanceExactFitInterference) {
  for (int segments : {16, 64, 128}) {
    for (bool far : {false, true}) {
      const Vec3 off = far ? kFar : Vec3::Zero();
      SCOPED_TRACE(std::to_string(segments) + (far ? " float32 far" : " double"));
      const BoltCase clear = bolt_case(4.95, segments, off, far);
      const BoltCase exact = bolt_case(5.0, segments, off, far);
      const BoltCase press = bolt_case(5.05, segments, off, far);
      EXPECT_FALSE(meshes_intersect(clear.plate, clear.bolt));
      EXPECT_TRUE(meshes_intersect(exact.plate, exact.bolt));  // faces touch
      EXPECT_TRUE(meshes_intersect(press.plate, press.bolt));
      EXPECT_EQ(deepest_vertex_depth(clear.plate, clear.bolt).depth, 0.0);
      EXPECT_EQ(deepest_vertex_depth(exact.plate, exact.bolt).depth, 0.0);
    }
  }
}

// Turned askew and placed far away, as assemblies place parts: the surfaces'
// pairing then runs in the smaller part's face axes, and must still find a
// press fit's crossing and a pin pushed 0.01 into the plate, and nothing for a
// clearance fit or a pin held 0.01 above it.
TEST(MeshIntersect, SurfacesOfPartsPlacedAskewMeetAsTheyWouldUnturned) {
  std::mt19937 rng(29);
  const auto turned = [](Mesh m, const Eigen::Matrix3d& r) {
    for (Eigen::Index k = 0; k < m.vertices.cols(); ++k)
      m.vertices.col(k) = r * m.vertices.col(k) + kFar;
    return float32(m);
  };
  for (int draw = 0; draw < 20; ++draw) {
    SCOPED_TRACE(draw);
    const Eigen::Matrix3d r = pd_test::random_rotation(rng);
    const Mesh plate = turned(plate_with_hole(40, 6, 5.0, 64), r);
    const PreparedMesh p(plate);
    EXPECT_FALSE(surfaces_meet(p, PreparedMesh(turned(cylinder({0, 0}, 4.95, -10, 16, 64), r))));
    EXPECT_TRUE(surfaces_meet(p, PreparedMesh(turned(cylinder({0, 0}, 5.05, -10, 16, 64), r))));
    EXPECT_FALSE(surfaces_meet(p, PreparedMesh(turned(cylinder({12, 9}, 2, 6.01, 20, 32), r))));
    EXPECT_TRUE(surfaces_meet(p, PreparedMesh(turned(cylinder({12, 9}, 2, 5.99, 20, 32), r))));
  }
}

TEST(MeshIntersect, BoltInterferenceDepthIsTheRimVertexDepth) {
  // The hole's rim vertices (radius R) lie inside the bolt (radius r, same
  // angles): each is (r − R)·cos(π/n) from the bolt's nearest side face.
  for (int segments : {16, 32, 128}) {
    const double R = 5.0, r = 5.05, want = (r - R) * std::cos(M_PI / segments);
    const BoltCase c = bolt_case(r, segments, Vec3::Zero(), false);
    const MeshDepthBound d = deepest_vertex_depth(c.plate, c.bolt);
    EXPECT_NEAR(d.depth, want, 1e-12);
    EXPECT_TRUE(d.vertex_of_a);
    ASSERT_GE(d.vertex, 0);
    // The direction moves the bolt (b) along the inward normal of its side face
    // nearest to that rim vertex: π/n off the vertex's radial direction.
    const Vec3 p = c.plate.vertices.col(d.vertex);
    EXPECT_NEAR(std::hypot(p.x(), p.y()), R, 1e-12);
    EXPECT_NEAR(d.direction.norm(), 1.0, 1e-12);
    EXPECT_NEAR(d.direction.dot(Vec3(p.x(), p.y(), 0).normalized()), -std::cos(M_PI / segments),
                1e-9);
    EXPECT_NEAR((p - d.surface_point).norm(), d.depth, 1e-12);

    // Far from the origin in float32: the same within float32 resolution there.
    const BoltCase f = bolt_case(r, segments, kFar, true);
    EXPECT_NEAR(deepest_vertex_depth(f.plate, f.bolt).depth, want, 4e-3);
  }
}

TEST(MeshIntersect, VertexDepthOfBoxesMatchesTheExactDepth) {
  const Mesh big = box({0, 0, 0}, {10, 10, 10}), b = box({9.5, 2, 2}, {20, 8, 8});
  // b's corners (9.5, 2|8, 2|8) are 0.5 inside big; big's vertices are outside b.
  MeshDepthBound d = deepest_vertex_depth(big, b);
  EXPECT_NEAR(d.depth, 0.5, 1e-12);
  EXPECT_FALSE(d.vertex_of_a);
  EXPECT_TRUE(d.direction.isApprox(Vec3::UnitX(), 1e-12));  // move b by +x
  const DepthSolution exact = exact_depth(verts(big), verts(b));
  EXPECT_NEAR(exact.depth, 0.5, 1e-12);
  EXPECT_TRUE(exact.direction.isApprox(d.direction, 1e-9));
  // Swapped roles: the vertex is now a's, and moving b (the big box) by −x separates.
  d = deepest_vertex_depth(b, big);
  EXPECT_NEAR(d.depth, 0.5, 1e-12);
  EXPECT_TRUE(d.vertex_of_a);
  EXPECT_TRUE(d.direction.isApprox(-Vec3::UnitX(), 1e-12));
  // Containment: the small box's corners are 4 deep; the exact depth is 6.
  d = deepest_vertex_depth(big, box({4, 4, 4}, {6, 6, 6}));
  EXPECT_NEAR(d.depth, 4.0, 1e-12);
}

TEST(MeshIntersect, VertexDepthNeverExceedsTheExactDepthOfConvexPairs) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int overlapping = 0;
  for (int k = 0; k < 40; ++k) {
    const Mesh a = cylinder({0, 0}, 3.0, 0, 4, 24);
    Mesh b = cylinder({2.0 * u(rng), 2.0 * u(rng)}, 1.0 + std::abs(u(rng)), -2, 3 + u(rng), 12);
    b = translated(b, Vec3(3 * u(rng), 3 * u(rng), 2 * u(rng)));
    const DepthSolution exact = exact_depth(verts(a), verts(b));
    const MeshDepthBound d = deepest_vertex_depth(a, b);
    EXPECT_LE(d.depth, exact.depth + 1e-12);
    if (d.depth > 0) ++overlapping;
  }
  EXPECT_GT(overlapping, 10);  // the bound is not trivially zero
}

TEST(MeshIntersect, LBracketWithABoxInItsCorner) {
  const Mesh l = l_bracket(40, 5, 20);  // legs [0,40]×[0,5] and [0,5]×[0,40]
  // In the corner with 1 mm gaps: the hulls overlap deeply, the parts do not.
  const Mesh gap = box({6, 6, 5}, {20, 20, 15});
  EXPECT_FALSE(meshes_intersect(l, gap));
  EXPECT_GT(exact_depth(verts(l), verts(gap)).depth, 5.0);
  // Seated on both inner faces: contact.
  EXPECT_TRUE(meshes_intersect(l, box({5, 5, 5}, {20, 20, 15})));
  EXPECT_EQ(deepest_vertex_depth(l, box({5, 5, 5}, {20, 20, 15})).depth, 0.0);
  // Sunk 0.3 into the horizontal leg: the box's lower corners are 0.3 deep.
  const Mesh sunk = box({6, 4.7, 5}, {20, 20, 15});
  EXPECT_TRUE(meshes_intersect(l, sunk));
  const MeshDepthBound d = deepest_vertex_depth(l, sunk);
  EXPECT_NEAR(d.depth, 0.3, 1e-12);
  EXPECT_FALSE(d.vertex_of_a);
  EXPECT_TRUE(d.direction.isApprox(Vec3::UnitY(), 1e-12));
  // A lower bound of the parts' depth, hence of the hulls' depth (an upper bound).
  EXPECT_LE(d.depth, exact_depth(verts(l), verts(sunk)).depth);
}

TEST(MeshIntersect, HollowBoxCavityIsNotMaterial) {
  const Mesh hollow = hollow_box({0, 0, 0}, {10, 10, 10}, 1.0);
  const PreparedMesh h(hollow);
  EXPECT_TRUE(h.closed());
  EXPECT_EQ(h.shells(), 2);
  const Mesh inside = box({3, 3, 3}, {7, 7, 7});
  EXPECT_FALSE(meshes_intersect(hollow, inside));  // in the void
  EXPECT_EQ(deepest_vertex_depth(hollow, inside).depth, 0.0);
  EXPECT_TRUE(meshes_intersect(box({0, 0, 0}, {10, 10, 10}), inside));  // solid: contained
  // Wholly inside the wall (between the shells): contained in material.
  const Mesh in_wall = box({0.2, 3, 3}, {0.8, 7, 7});
  EXPECT_TRUE(meshes_intersect(hollow, in_wall));
  EXPECT_NEAR(deepest_vertex_depth(hollow, in_wall).depth, 0.2, 1e-12);
}

TEST(MeshIntersect, OpenMeshIsASurfaceOnly) {
  Mesh open = box({0, 0, 0}, {10, 10, 10});
  open.triangles.conservativeResize(3, 10);  // drop the last two triangles: one side open
  const PreparedMesh o(open);
  EXPECT_FALSE(o.closed());
  EXPECT_FALSE(meshes_intersect(open, box({4, 4, 4}, {6, 6, 6})));  // inside: not found
  EXPECT_TRUE(meshes_intersect(open, box({4, 4, -1}, {6, 6, 6})));  // crosses the bottom
  const MeshDepthBound d = deepest_vertex_depth(open, box({4, 4, -1}, {6, 6, 6}));
  EXPECT_FALSE(d.tested_in_a);
  EXPECT_TRUE(d.tested_in_b);
  EXPECT_EQ(d.depth, 0.0);  // nothing of the open box inside the small one
}

TEST(MeshIntersect, SelfIntersectingMeshNeverCrashes) {
  // Two overlapping boxes exported as one mesh without a boolean union.
  const Mesh two = joined({box({0, 0, 0}, {10, 10, 10}), box({5, 5, 5}, {15, 15, 15})});
  const PreparedMesh p(two);
  EXPECT_TRUE(p.closed());
  EXPECT_TRUE(meshes_intersect(two, box({1, 1, 1}, {2, 2, 2})));         // in one shell only
  EXPECT_TRUE(meshes_intersect(two, box({9, 9, 9}, {11, 11, 11})));      // crosses surfaces
  EXPECT_FALSE(meshes_intersect(two, box({20, 20, 20}, {21, 21, 21})));  // apart
  // The corner (2, 2, 2) is 2 from the first box's faces.
  EXPECT_NEAR(deepest_vertex_depth(two, box({1.5, 1.5, 1.5}, {2, 2, 2})).depth, 2.0, 1e-12);
}

TEST(MeshIntersect, DegenerateTrianglesCountAsSegments) {
  // A needle triangle (collinear corners) piercing a box face, and one with a
  // repeated corner: their segment is their whole point set.
  Mesh needle;
  needle.vertices.resize(3, 3);
  needle.vertices << 5, 5, 5,  //
      5, 5, 5,                 //
      -1, 0.5, 3;
  needle.triangles.resize(3, 1);
  needle.triangles << 0, 1, 2;
  const Mesh b = box({0, 0, 0}, {10, 10, 10});
  EXPECT_TRUE(meshes_intersect(b, needle));
  needle.vertices.row(2) << -3, -2, -1;
  EXPECT_FALSE(meshes_intersect(b, needle));
  needle.triangles << 0, 0, 2;
  needle.vertices.row(2) << -3, -2, 1;
  EXPECT_TRUE(meshes_intersect(b, needle));
}

TEST(MeshIntersect, BadMeshesAreRejected) {
  Mesh points;
  points.vertices = Points::Zero(3, 4);
  EXPECT_THROW(PreparedMesh{points}, std::invalid_argument);
  Mesh bad = box({0, 0, 0}, {1, 1, 1});
  bad.triangles(0, 3) = 99;
  EXPECT_THROW(PreparedMesh{bad}, std::invalid_argument);
}

TEST(MeshIntersect, OutsideDistanceAgreesWithTheRayTest) {
  // The oriented fast path (side of the nearest face) and the ray test must
  // agree everywhere, also on an inward-oriented copy (ray test only) and on
  // the hollow box's inward cavity shell.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-25.0, 25.0);
  for (const Mesh& m : {plate_with_hole(40, 6, 5, 16), flipped(plate_with_hole(40, 6, 5, 16)),
                        translated(hollow_box({0, 0, 0}, {20, 20, 20}, 2), Vec3(-10, -10, -7))}) {
    const PreparedMesh p(m);
    int inside = 0;
    for (int k = 0; k < 2000; ++k) {
      const Vec3 x(u(rng), u(rng), 0.4 * u(rng));
      const double want = p.inside(x) ? 0.0 : p.distance(x);
      inside += want == 0.0;
      ASSERT_NEAR(p.outside_distance(x), want, 1e-12) << x.transpose();
    }
    EXPECT_GT(inside, 50);
  }
}

TEST(MeshIntersect, ANearFaceHintGivesTheSameSignedDistance) {
  // A run of nearby queries passes each one's nearest face to the next; the
  // answer must be the query's own, whatever the hint (a far face, none, a
  // face of the other side of the plate).
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-25.0, 25.0);
  for (const Mesh& m : {plate_with_hole(40, 6, 5, 16),
                        translated(plate_with_hole(40, 6, 5, 48), Vec3(3e4, 0, 0))}) {
    const PreparedMesh p(m);
    const Vec3 origin = p.face(0)[0];
    int hint = -1, inside = 0;
    for (int k = 0; k < 2000; ++k) {
      const Vec3 x = origin + Vec3(u(rng), u(rng), 0.4 * u(rng));
      if (k % 5 == 0) hint = static_cast<int>(rng() % p.faces());  // a face anywhere
      Vec3 want_nearest, got_nearest;
      const double want = p.signed_distance(x, &want_nearest);
      const double got = p.signed_distance(x, &got_nearest, nullptr, &hint);
      ASSERT_NEAR(got, want, 1e-12 * (1 + x.cwiseAbs().maxCoeff())) << k;
      ASSERT_EQ(got > 0, want > 0) << k;
      ASSERT_GE(hint, 0);
      inside += want > 0;
    }
    EXPECT_GT(inside, 50);
  }
}

TEST(MeshIntersect, UnsignedDistanceIsTheSignedOnesMagnitude) {
  // The same nearest point, normal and face, without the inside test: on a
  // plate with a hole (float32, far from the origin) at points inside, outside
  // and in the hole.
  const Mesh plate = float32(translated(plate_with_hole(40, 6, 5, 32), Vec3(20000, -3000, 500)));
  const PreparedMesh m(plate);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-25, 25);
  for (int i = 0; i < 200; ++i) {
    const Vec3 p = Vec3(20000, -3000, 500) + Vec3(u(rng), u(rng), u(rng) / 4);
    Vec3 ns, nu, fs, fu;
    int face_s = -1, face_u = -1;
    const double s = m.signed_distance(p, &ns, &fs, &face_s);
    const double d = m.unsigned_distance(p, &nu, &fu, &face_u);
    EXPECT_EQ(d, std::abs(s)) << i;
    EXPECT_EQ(nu, ns) << i;
    EXPECT_EQ(fu, fs) << i;
    EXPECT_EQ(face_u, face_s) << i;
  }
}
