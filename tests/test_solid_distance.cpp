// SolidDistance's models against the exact distance: every plane, hole and
// wedge bound of a box's local model holds at the points of the box inside the
// solid, and the surface depth never falls below the deepest vertex.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include "corpus/cad_shapes.h"
#include "geometry/solid_distance.h"
#include "random_rotation.h"

namespace pd {
namespace {

using pd_test::random_rotation;

namespace sh = shapes;

// Models with holes and wedges, and the points checked; `wide_holes`: models
// with a hole whose normals lie more than 60° apart (a bore and a shoulder).
struct ModelCounts {
  int holes = 0, several_holes = 0, wide_holes = 0, wedges = 0, checked = 0;
};

// A rotation drawn uniformly (a random unit quaternion).
// Checks every plane, hole and wedge bound of s's models about framed boxes
// (a random rotation, the origin at `centre(rng)`, sides up to 0.4 of `scale`,
// some twenty times longer than thick, a margin up to half of `scale`):
// min(sd(x), margin) is at most each bound at points x of the box inside the
// solid, sd from `truth` (the same solid, distances exact).
template <class Centre>
ModelCounts check_box_planes(const SolidDistance& s, const SolidDistance& truth, double scale,
                             Centre centre, std::mt19937& rng, int trials) {
  std::uniform_real_distribution<double> u(0, 1);
  ModelCounts n;
  for (int trial = 0; trial < trials; ++trial) {
    FramedBox box;
    box.frame.origin = centre(rng);
    box.frame.R = random_rotation(rng);
    Vec3 half = Vec3::Constant(scale * (0.02 + 0.4 * u(rng)));
    if (trial % 2) half[trial % 3] *= 0.05;  // a slab, as about a seated face
    const Vec3 shift = 0.5 * scale * Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
    box.lo = shift - half;
    box.hi = shift + half;
    const double margin = scale * (0.01 + 0.5 * u(rng));
    const LocalPlanes m = s.local_planes(box, margin);
    EXPECT_EQ(m.margin, margin);
    n.holes += !m.holes.empty();
    n.several_holes += m.holes.size() > 1;
    n.wide_holes += std::any_of(m.holes.begin(), m.holes.end(), [](const LocalPlanes::Hole& h) {
      for (const FacePlane& p : h.planes)
        for (const FacePlane& q : h.planes)
          if (p.normal.dot(q.normal) < 0.5) return true;
      return false;
    });
    n.wedges += !m.wedges.empty();
    for (int k = 0; k < 60; ++k) {
      // Half the points on the box's faces, where the margin is tightest.
      Vec3 y = box.lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(box.hi - box.lo);
      if (k % 2) y[k % 3] = k % 4 < 2 ? box.lo[k % 3] : box.hi[k % 3];
      const double sd = truth.at(box.frame.world(y)).lower;
      if (sd <= 0) continue;
      ++n.checked;
      const double capped = std::min(sd, m.margin);
      const double eps = 1e-12 * (1 + box.frame.origin.norm());  // the planes' own rounding
      for (const FacePlane& q : m.supporting) EXPECT_LE(capped, q.at(y) + m.slack + eps);
      for (const LocalPlanes::Hole& h : m.holes) {
        double most = -INFINITY;
        for (const FacePlane& q : h.planes) most = std::max(most, q.at(y));
        EXPECT_LE(capped, h.kappa * (most + h.slack) + eps) << "trial " << trial;
      }
      for (const LocalPlanes::Wedge& w : m.wedges)
        EXPECT_LE(capped, w.kappa * (std::max(w.p.at(y), w.q.at(y)) + w.slack) + eps)
            << "trial " << trial;
    }
  }
  return n;
}

TEST(LocalPlanes, EveryBoundHoldsAtAShoulder) {
  // Framed boxes about a stepped shaft's shoulder: one shell, near the origin
  // in double and far from it in float32; and the same solid exported as two
  // bodies face to face (shank and head), whose union's distance from inside
  // is known only from below, so the truth is the one-shell solid's.
  const int n = 32;
  const Vec3 far(28000, 3000, -900);
  std::uniform_real_distribution<double> u(0, 1);
  for (const int kind : {0, 1, 2}) {
    const Vec3 origin = kind == 1 ? far : Vec3::Zero();
    const Mesh shaft = sh::stepped_shaft(3, 5, 0, 10, 12, n);
    const Mesh bolt =
        sh::joined({sh::cylinder({0, 0}, 3, 0, 10, n), sh::cylinder({0, 0}, 5, 10, 12, n)});
    const SolidDistance truth(kind == 1 ? sh::float32(sh::translated(shaft, far)) : shaft);
    const SolidDistance s(kind == 2   ? bolt
                          : kind == 1 ? sh::float32(sh::translated(shaft, far))
                                      : shaft);
    ASSERT_EQ(s.exact(), kind != 2);
    std::mt19937 rng(5 + kind);
    const ModelCounts counts = check_box_planes(
        s, truth, 1.0,
        [&](std::mt19937& g) {
          const double angle = 2 * M_PI * u(g), rad = 2.6 + 0.8 * u(g);
          return Vec3(origin +
                      Vec3(rad * std::cos(angle), rad * std::sin(angle), 9.6 + 0.8 * u(g)));
        },
        rng, 200);
    EXPECT_GT(counts.wedges, 10) << "kind " << kind;  // the shoulder is modelled
    EXPECT_GT(counts.checked, 2000) << "kind " << kind;
  }
}

TEST(LocalPlanes, EveryBoundHoldsAboutHoles) {
  // A board's 0.5 mm hole, wholly within many boxes' margins; a plate's 5 mm
  // bore, which spans many boxes; a drilled board's row of 0.75 mm holes 2 mm
  // apart, where boxes see two holes; a housing's bore ending at a shoulder
  // (a ring seated there), where the bore's facets and the shoulder's plane
  // make one hole whose normals are 90° apart.
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(0, 1);
  const auto about_hole = [&](double radius, double thickness) {
    return [=, &u](std::mt19937& g) {
      const double angle = 2 * M_PI * u(g), rad = radius * (1 + 0.3 * u(g));
      return Vec3(rad * std::cos(angle), rad * std::sin(angle), thickness * u(g));
    };
  };
  struct Case {
    Mesh mesh;
    double scale;
    std::function<Vec3(std::mt19937&)> centre;
  };
  const double pitch = 2;
  const Case cases[] = {
      {sh::plate_with_hole(2.54, 1.6, 0.5, 32), 0.5, about_hole(0.5, 1.6)},
      {sh::plate_with_hole(40, 6, 5, 64), 5, about_hole(5, 6)},
      {sh::drilled_board(3, 1, pitch, 1.6, 0.75, 32), 0.5,
       [&](std::mt19937& g) {
         return Vec3(pitch * (0.5 + u(g)), pitch * (0.5 * u(g) - 0.25) + 0.5 * pitch, 1.6 * u(g));
       }},
      {sh::revolution({{3, 0}, {10, 0}, {10, 8}, {5, 8}, {5, 4}, {3, 4}}, 64), 0.5,
       [&](std::mt19937& g) {
         const double angle = 2 * M_PI * u(g), rad = 4.4 + 0.8 * u(g);
         return Vec3(rad * std::cos(angle), rad * std::sin(angle), 3.6 + 0.8 * u(g));
       }}};
  for (size_t k = 0; k < 4; ++k) {
    const SolidDistance s(cases[k].mesh);
    const ModelCounts counts = check_box_planes(s, s, cases[k].scale, cases[k].centre, rng, 200);
    EXPECT_GT(counts.holes, 40) << "case " << k;
    EXPECT_GT(counts.checked, 2000) << "case " << k;
    if (k == 2) {
      EXPECT_GT(counts.several_holes, 0);
    }
    // The bore's facets and the shoulder as one hole (the bisector of the
    // normals farthest apart, not their mean: 22 such models with the mean).
    if (k == 3) {
      EXPECT_GT(counts.wide_holes, 50);
    }
  }
}

// Two models equal to the last bit.
void expect_same(const LocalPlanes& x, const LocalPlanes& y) {
  const auto same = [](const FacePlane& p, const FacePlane& q) {
    return p.normal == q.normal && p.offset == q.offset;
  };
  ASSERT_EQ(x.supporting.size(), y.supporting.size());
  for (size_t k = 0; k < x.supporting.size(); ++k)
    EXPECT_TRUE(same(x.supporting[k], y.supporting[k]));
  ASSERT_EQ(x.holes.size(), y.holes.size());
  for (size_t k = 0; k < x.holes.size(); ++k) {
    ASSERT_EQ(x.holes[k].planes.size(), y.holes[k].planes.size());
    for (size_t j = 0; j < x.holes[k].planes.size(); ++j)
      EXPECT_TRUE(same(x.holes[k].planes[j], y.holes[k].planes[j]));
    EXPECT_EQ(x.holes[k].kappa, y.holes[k].kappa);
    EXPECT_EQ(x.holes[k].slack, y.holes[k].slack);
  }
  ASSERT_EQ(x.wedges.size(), y.wedges.size());
  for (size_t k = 0; k < x.wedges.size(); ++k) {
    EXPECT_TRUE(same(x.wedges[k].p, y.wedges[k].p));
    EXPECT_TRUE(same(x.wedges[k].q, y.wedges[k].q));
    EXPECT_EQ(x.wedges[k].kappa, y.wedges[k].kappa);
    EXPECT_EQ(x.wedges[k].slack, y.wedges[k].slack);
  }
  EXPECT_EQ(x.slack, y.slack);
  EXPECT_EQ(x.margin, y.margin);
}

TEST(LocalPlanes, KeptFacesGiveTheSameModels) {
  // A search keeps the faces it took into its frame (FrameFaces) across its
  // boxes: the models must be those built without, to the last bit. Boxes
  // about a float32 shoulder far from the origin, a drilled board's holes and
  // a union of two shells, one kept-faces object asked about all of them in
  // turn (it starts over when the solid or the frame changes).
  const Vec3 far(28000, 3000, -900);
  const Mesh shaft = sh::float32(sh::translated(sh::stepped_shaft(3, 5, 0, 10, 12, 32), far));
  const Mesh board = sh::drilled_board(3, 1, 2, 1.6, 0.75, 32);
  const Mesh bolt =
      sh::joined({sh::cylinder({0, 0}, 3, 0, 10, 32), sh::cylinder({0, 0}, 5, 10, 12, 32)});
  const SolidDistance solids[] = {SolidDistance(shaft), SolidDistance(board), SolidDistance(bolt)};
  const Vec3 centres[] = {far + Vec3(3, 0, 10), Vec3(3, 1, 0.8), Vec3(3, 0, 10)};
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(0, 1);
  FrameFaces kept;
  int models = 0;
  for (int round = 0; round < 2; ++round)
    for (size_t k = 0; k < 3; ++k) {
      FramedBox box;
      box.frame.origin = centres[k];
      box.frame.R = random_rotation(rng);
      for (int trial = 0; trial < 150; ++trial) {
        const Vec3 half = Vec3::Constant(0.02 + 0.5 * u(rng));
        const Vec3 shift = 3 * Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
        box.lo = shift - half;
        box.hi = shift + half;
        const double margin = 0.01 + 0.3 * u(rng);
        const LocalPlanes fresh = solids[k].local_planes(box, margin);
        expect_same(fresh, solids[k].local_planes(box, margin, &kept));
        models += !fresh.empty();
      }
    }
  EXPECT_GT(models, 300);
}

TEST(LocalPlanes, ANeedleTriangleDoesNotHideTheSurface) {
  // A unit cube whose top face has a vertex in the middle of its front edge,
  // closed by a needle (a collinear triangle, as float32 exports make them)
  // against the front face's edge: the needle lies on that edge, so the cube's
  // planes still model it.
  Mesh cube;
  cube.vertices.resize(3, 9);
  cube.vertices << 0, 1, 1, 0, 0, 1, 1, 0, 0.5,  //
      0, 0, 1, 1, 0, 0, 1, 1, 0,                 //
      0, 0, 0, 0, 1, 1, 1, 1, 1;
  const std::vector<Eigen::Vector3i> tris{{0, 2, 1}, {0, 3, 2}, {4, 8, 7}, {8, 5, 6}, {8, 6, 7},
                                          {5, 8, 4}, {0, 1, 5}, {0, 5, 4}, {3, 7, 6}, {3, 6, 2},
                                          {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};
  cube.triangles.resize(3, static_cast<long>(tris.size()));
  for (size_t t = 0; t < tris.size(); ++t) cube.triangles.col(static_cast<long>(t)) = tris[t];
  const SolidDistance s(cube);
  ASSERT_TRUE(s.closed());
  ASSERT_TRUE(s.mesh().has_segments());
  const Vec3 c(0.5, 0.1, 0.9);
  FramedBox box;  // the world's own frame
  box.lo = c.array() - 0.05;
  box.hi = c.array() + 0.05;
  const double margin = 0.5;
  const LocalPlanes m = s.local_planes(box, margin);
  ASSERT_FALSE(m.supporting.empty());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (int k = 0; k < 200; ++k) {
    const Vec3 x = c + Vec3(u(rng), u(rng), u(rng));
    for (const FacePlane& q : m.supporting)
      EXPECT_LE(std::min(s.at(x).lower, margin), q.at(x) + m.slack + 1e-12);
  }
}

TEST(SurfaceDepth, NeverBelowTheDeepestVertexWhateverTheBudget) {
  namespace sh = shapes;
  // `m` turned about x, then y, and lowered until its lowest point is `depth`
  // below z = 10 at (10, 10), the top of the blocks below.
  const auto sunk = [](Mesh m, double about_x, double about_y, double depth) {
    const Eigen::Matrix3d r =
        (Eigen::AngleAxisd(about_x, Vec3::UnitX()) * Eigen::AngleAxisd(about_y, Vec3::UnitY()))
            .toRotationMatrix();
    for (Eigen::Index k = 0; k < m.vertices.cols(); ++k) m.vertices.col(k) = r * m.vertices.col(k);
    const double low = m.vertices.row(2).minCoeff();
    for (Eigen::Index k = 0; k < m.vertices.cols(); ++k)
      m.vertices.col(k) += Vec3(10, 10, 10 - depth - low);
    return m;
  };
  // A cube on its corner, that corner 0.3 into a block: only the corner is deep.
  // The points measured are the ones that matter: a point is skipped only
  // when a measured neighbour shows it shallower than the deepest found.
  const Mesh corner =
      sunk(sh::box(Vec3(-2, -2, -2), Vec3(2, 2, 2)), std::atan(std::sqrt(0.5)), M_PI / 4, 0.3);
  // A small foil tilted 0.6 into a block: its corners, all within 0.8 of one
  // another, lie at many depths (points near a shallow one may still be deeper).
  const Mesh foil =
      sunk(sh::box(Vec3(-0.25, -0.25, -0.025), Vec3(0.25, 0.25, 0.025)), 0.7, 0.4, 0.6);
  const std::pair<Mesh, Mesh> cases[] = {
      {sh::box(Vec3(5, 5, 7), Vec3(15, 5.05, 13)), sh::box(Vec3(0, 0, 0), Vec3(20, 20, 10))},
      {foil, sh::box(Vec3(0, 0, 0), Vec3(20, 20, 10))},
      {corner, sh::box(Vec3(0, 0, 0), Vec3(20, 20, 10))},
      {sh::cylinder({0, 0}, 5.3, -4, 10, 32), sh::plate_with_hole(40, 6, 5, 32)},
      {sh::box(Vec3(3, 3, 3), Vec3(20, 12, 9.5)),
       sh::hollow_box(Vec3(0, 0, 0), Vec3(30, 20, 10), 1.5)}};
  // As given, and turned askew far from the origin (the samples are then
  // kept to the other part's box in its own axes).
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(1.1, Vec3(-2, 1, 4).normalized()).toRotationMatrix();
  const auto turned = [&](Mesh m) {
    for (Eigen::Index k = 0; k < m.vertices.cols(); ++k)
      m.vertices.col(k) = turn * m.vertices.col(k) + Vec3(2.7e4, -1.9e4, 6.1e3);
    return m;
  };
  for (const bool askew : {false, true}) {
    for (const auto& [a0, b0] : cases) {
      const Mesh a = askew ? turned(a0) : a0, b = askew ? turned(b0) : b0;
      const SolidDistance sa(a), sb(b);
      const MeshDepthBound vertex = deepest_vertex_depth(sa.mesh(), sb.mesh());
      ASSERT_GT(vertex.depth, 0.0);
      for (long budget : {0L, 100L, 20000L}) {
        const double surface = std::max(surface_depth(sa.mesh(), sb, budget).depth,
                                        surface_depth(sb.mesh(), sa, budget).depth);
        EXPECT_GE(surface, vertex.depth - 1e-9) << budget << (askew ? " askew" : "");
      }
    }
  }
  // A rod through a wall whose corners all lie outside it: only the samples
  // inside the wall's faces see it.
  const Mesh wall = sh::box(Vec3(0, 0, 0), Vec3(40, 40, 1));
  const Mesh rod = sh::cylinder({20, 20}, 1.0, -10, 10, 16);
  const SolidDistance s_wall(wall), s_rod(rod);
  EXPECT_EQ(deepest_vertex_depth(s_wall.mesh(), s_rod.mesh()).depth, 0.0);
  EXPECT_GT(surface_depth(s_wall.mesh(), s_rod).depth, 0.5);
}

TEST(SurfaceDepth, ADeepPieceIsFollowedFirst) {
  // A pin seated in its bore (256 slivers 80 mm long along the contact, none
  // deeper than the chords' sag: split to the spacing they take ~37,000
  // samples) and a foil through the plate beside it, every corner of the foil
  // outside the plate. The deepest pieces are followed first (pieces outside
  // the plate's box ranked by their distance to it), so the foil's middle is
  // found within a small budget, whichever part the file lists first.
  namespace sh = shapes;
  const Mesh pin = sh::cylinder({0, 0}, 5, -40, 40, 128);
  const Mesh foil = sh::box(Vec3(12, -30, -30), Vec3(12.05, 30, 30));
  const SolidDistance plate(sh::plate_with_hole(40, 6, 5, 128));
  EXPECT_LT(surface_depth(PreparedMesh(pin), plate).depth, 0.01);
  for (const Mesh& part : {sh::joined({pin, foil}), sh::joined({foil, pin})}) {
    const SurfaceDepth d = surface_depth(PreparedMesh(part), plate, 300);
    EXPECT_GT(d.depth, 2.5);  // of at most 3, half the plate's thickness
    EXPECT_NEAR(d.at.x(), 12.025, 0.025 + 1e-9);
  }
}

TEST(SurfaceDepth, AsAGuardItFollowsOnlyWhatCanDecide) {
  // The same pin and foil, sought only above a tolerance of 0.1 (a pair whose
  // thickness is bracketed, batch/refine.cpp): pieces that cannot reach it are
  // not split, and the foil is still found as deep as by the whole search.
  namespace sh = shapes;
  const Mesh pin = sh::cylinder({0, 0}, 5, -40, 40, 128);
  const Mesh foil = sh::box(Vec3(12, -30, -30), Vec3(12.05, 30, 30));
  const SolidDistance plate(sh::plate_with_hole(40, 6, 5, 128));
  const SurfaceDepth whole = surface_depth(PreparedMesh(sh::joined({pin, foil})), plate, 300);
  const SurfaceDepth guard = surface_depth(PreparedMesh(sh::joined({pin, foil})), plate, 300, 0.1);
  EXPECT_GT(guard.depth, 2.5);
  EXPECT_NEAR(guard.depth, whole.depth, 0.05);
  // The pin alone stays below the tolerance: a guard that finds nothing.
  EXPECT_LT(surface_depth(PreparedMesh(pin), plate, 300, 0.1).depth, 0.01);
}

}  // namespace
}  // namespace pd

namespace pd {
namespace {

// A union's inside against its shells' own ray tests: a bolt exported as two
// bodies face to face (a 32-sided shank under a hexagonal head, float32, far
// from the origin) and a flipped third body (its faces inward: the shortcut by
// the nearest face must not trust it). Inside the union exactly where some
// shell holds the point; the lower bound's magnitude is the distance to the
// nearest face either way.
TEST(SolidDistance, AUnionIsInsideWhereSomeShellIs) {
  namespace sh = shapes;
  const Vec3 far(21500.5, -3070.25, 880.0);
  const std::vector<Mesh> bodies{
      sh::float32(sh::translated(sh::cylinder({0, 0}, 4, 0, 20, 32), far)),
      sh::float32(sh::translated(sh::prism(sh::circle({0, 0}, 7, 6), 20, 25), far)),
      sh::float32(sh::translated(sh::flipped(sh::box(Vec3(5, 5, 2), Vec3(9, 9, 6))), far))};
  const SolidDistance bolt(sh::joined(bodies));
  ASSERT_FALSE(bolt.exact());
  ASSERT_TRUE(bolt.closed());
  std::vector<PreparedMesh> shells;
  for (const Mesh& m : bodies) shells.emplace_back(m);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-10, 10), h(-2, 27);
  int inside = 0, near_face = -1;
  for (int k = 0; k < 4000; ++k) {
    Vec3 p = far + Vec3(u(rng), u(rng), h(rng));
    // Some points on a corner's level or line, where rays run along faces.
    const Mesh& m = bodies[rng() % bodies.size()];
    const Vec3 v = m.vertices.col(rng() % m.vertices.cols());
    if (k % 4 == 1) p.z() = v.z();
    if (k % 4 == 2) p.head<2>() = v.head<2>();
    const bool want = std::any_of(shells.begin(), shells.end(),
                                  [&](const PreparedMesh& s) { return s.inside(p); });
    const DistanceBounds d = bolt.at(p, k % 2 ? &near_face : nullptr);
    EXPECT_EQ(d.lower > 0, want) << k;
    EXPECT_NEAR(std::abs(d.lower), bolt.mesh().distance(p), 1e-9) << k;
    inside += want;
  }
  EXPECT_GT(inside, 300);
}

}  // namespace
}  // namespace pd
