// The overlap thickness against exact references: the Chebyshev centre of two
// convex polytopes' intersection (an LP solved by vertex enumeration), and
// nonconvex CAD shapes whose overlap is known by construction.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "corpus/cad_shapes.h"
#include "geometry/hull.h"
#include "lp_reference.h"
#include "solve/overlap_thickness.h"

namespace pd {
namespace {

using Outcome = ThicknessResult::Outcome;
namespace sh = shapes;

// A random convex polytope (hull of points in a ball about `centre`) as an
// outward-oriented mesh, and its facet planes as affine functions s(x) ≥ 0 inside.
struct Polytope {
  Mesh mesh;
  std::vector<Affine> planes;
};

Polytope random_polytope(std::mt19937& rng, const Vec3& centre, double radius, int n) {
  std::normal_distribution<double> g(0, 1);
  Points p(3, n);
  for (int k = 0; k < n; ++k)
    p.col(k) = centre + radius * Vec3(g(rng), g(rng), g(rng)).normalized();
  HullFacets f;
  EXPECT_TRUE(hull_facets(p, f));
  Polytope out;
  out.mesh.vertices = p;
  out.mesh.triangles.resize(3, f.triangles.size());
  for (size_t t = 0; t < f.triangles.size(); ++t) {
    auto tri = f.triangles[t];
    const Vec3 n = (p.col(tri[1]) - p.col(tri[0])).cross(p.col(tri[2]) - p.col(tri[0]));
    if (n.dot(f.normals[t]) < 0) std::swap(tri[1], tri[2]);
    out.mesh.triangles.col(t) = Eigen::Vector3i(tri[0], tri[1], tri[2]);
    out.planes.push_back({-f.offsets[t], -f.normals[t]});  // normal·x + offset ≤ 0 inside
  }
  return out;
}

bool brackets(const ThicknessResult& r, double exact, double slack) {
  return r.lower <= exact + slack && exact <= r.upper + slack;
}

TEST(OverlapThickness, ConvexPairsBracketTheChebyshevCentreAndDecideBothWays) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  int decided = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const Vec3 far = trial % 2 ? Vec3(21000, -3000, 500) : Vec3::Zero();
    const Polytope a = random_polytope(rng, far, 1.0, 10 + trial % 7);
    const Polytope b = random_polytope(rng, far + Vec3(u(rng), u(rng), u(rng)) * 1.2, 0.8, 9);
    std::vector<Affine> both = a.planes;
    both.insert(both.end(), b.planes.begin(), b.planes.end());
    const double exact =
        2 * std::max(0.0, max_min_affine_reference(both, far.array() - 3, far.array() + 3));
    const SolidDistance sa(a.mesh), sb(b.mesh);
    const double slack = 1e-9 * (1 + far.norm());
    if (exact < 1e-3) continue;  // touching or apart: the mesh test's business
    const ThicknessResult below = overlap_thickness(sa, sb, 1.25 * exact);
    const ThicknessResult above = overlap_thickness(sa, sb, 0.8 * exact);
    EXPECT_EQ(below.outcome, Outcome::kBelow) << "trial " << trial << " exact " << exact;
    EXPECT_EQ(above.outcome, Outcome::kAbove) << "trial " << trial << " exact " << exact;
    EXPECT_TRUE(brackets(below, exact, slack)) << below.lower << " " << exact << " " << below.upper;
    EXPECT_TRUE(brackets(above, exact, slack)) << above.lower << " " << exact << " " << above.upper;
    decided += below.outcome == Outcome::kBelow && above.outcome == Outcome::kAbove;
  }
  EXPECT_GE(decided, 10);  // the generator made real overlaps
}

// The 2-D overlap of a regular n-gon pin of circumradius R turned half a step
// against an equal n-gon bore: n triangles, each a pin vertex cut off by a bore
// chord. The thickest ball is one such triangle's incircle.
double half_step_pin_thickness(double R, int n) {
  const double a = R * std::cos(M_PI / n);  // the bore chord's distance from the axis
  const Eigen::Vector2d apex(R, 0), q(R * std::cos(2 * M_PI / n), R * std::sin(2 * M_PI / n));
  const double t = (a - apex.x()) / (q.x() - apex.x());
  const Eigen::Vector2d c1 = apex + t * (q - apex), c2(c1.x(), -c1.y());
  const double ab = (apex - c1).norm(), bc = (c1 - c2).norm(), ca = (c2 - apex).norm();
  const double area = 0.5 * bc * (apex.x() - a);
  return 2 * area / (0.5 * (ab + bc + ca));  // 2 × inradius
}

TEST(OverlapThickness, PinHalfAStepTurnedInItsBoreIsThinAndBracketed) {
  for (int n : {16, 32, 64}) {
    const Mesh plate = sh::plate_with_hole(40, 6, 5, n);
    const Mesh pin = sh::prism(sh::circle({0, 0}, 5, n, M_PI / n), -4, 10);
    const double exact = half_step_pin_thickness(5, n);
    const ThicknessResult r =
        overlap_thickness(SolidDistance(pin), SolidDistance(plate), 1.5 * exact);
    EXPECT_EQ(r.outcome, Outcome::kBelow) << n << " segments";
    EXPECT_TRUE(brackets(r, exact, 1e-9)) << r.lower << " " << exact << " " << r.upper;
    // Thin everywhere along the bore: decided from the planes, not by visiting
    // the sliver at the tolerance's scale (a count, not a time).
    EXPECT_LT(r.evaluations, 60000) << n << " segments";
    // Where it is thick enough, the same pair is an interference.
    const ThicknessResult strict =
        overlap_thickness(SolidDistance(pin), SolidDistance(plate), 0.5 * exact);
    EXPECT_EQ(strict.outcome, Outcome::kAbove) << n << " segments";
  }
}

TEST(OverlapThickness, ShoulderedPinSeatedOnItsBoreIsThinAndBracketed) {
  // A pin whose head (r 5) rests on the plate around its bore (r 3): at the
  // shoulder the pin's complement is a union of wedges (a shank facet's outer
  // side below the head), which no convex-hole model covers; the slivers run
  // up into that corner. Turned half a step, far from the origin, float32.
  const int n = 48;
  const Vec3 far(21000, -4000, 1500);
  const Mesh plate = sh::float32(sh::translated(sh::plate_with_hole(40, 6, 3, n), far));
  Mesh pin = sh::stepped_shaft(3, 5, -4, 6, 8, n);
  pin.vertices = Eigen::AngleAxisd(M_PI / n, Vec3::UnitZ()).toRotationMatrix() * pin.vertices;
  pin = sh::float32(sh::translated(pin, far));
  const SolidDistance a(pin), b(plate);
  ASSERT_TRUE(a.exact());
  const double exact = half_step_pin_thickness(3, n), noise = 4 * std::max(a.noise(), b.noise());
  const ThicknessResult r = overlap_thickness(a, b, 0.05);
  EXPECT_EQ(r.outcome, Outcome::kBelow);
  EXPECT_TRUE(brackets(r, exact, noise)) << r.lower << " " << exact << " " << r.upper;
  // The shoulder's circle is certified by wedges at a coarse scale, not cell by
  // cell at the tolerance's (a count, not a time: 3,362 with wedges, 40,604
  // without).
  EXPECT_LT(r.evaluations, 12000);
}

// Checks every plane, hole and wedge bound of s's models about boxes centred
// by `centre(rng)` (half-size up to 0.4 of `scale`) against the exact distance
// at points of the box inside the solid; counts the models with holes and
// wedges and the points checked.
struct ModelCounts {
  int holes = 0, several_holes = 0, wedges = 0, checked = 0;
};
template <class Centre>
ModelCounts check_local_planes(const SolidDistance& s, double scale, Centre centre,
                               std::mt19937& rng, int trials) {
  std::uniform_real_distribution<double> u(0, 1);
  ModelCounts n;
  for (int trial = 0; trial < trials; ++trial) {
    const Vec3 c = centre(rng);
    const Vec3 half = Vec3::Constant(scale * (0.02 + 0.4 * u(rng)));
    // Both reaches the branch and bound may ask for; the counts are the widest's.
    const LocalPlanes wide = s.local_planes(c, std::abs(s.at(c).lower), half.norm());
    n.holes += !wide.holes.empty();
    n.several_holes += wide.holes.size() > 1;
    n.wedges += !wide.wedges.empty();
    const LocalPlanes near =
        s.local_planes(c, std::abs(s.at(c).lower), half.norm(), SolidDistance::Widen::kWhenEmpty);
    for (const LocalPlanes* model : {&wide, &near})
      for (int k = 0; k < 40; ++k) {
        const LocalPlanes& m = *model;
        const Vec3 x = c + Vec3(2 * u(rng) - 1, 2 * u(rng) - 1, 2 * u(rng) - 1).cwiseProduct(half);
        const double sd = s.at(x).lower;
        if (sd <= 0) continue;
        ++n.checked;
        const double eps = 1e-12 * (1 + x.norm());  // the planes' own rounding
        for (const FacePlane& q : m.supporting) EXPECT_LE(sd, q.at(x) + m.slack + eps);
        for (const LocalPlanes::Hole& h : m.holes) {
          double most = -INFINITY;
          for (const FacePlane& q : h.planes) most = std::max(most, q.at(x));
          EXPECT_LE(sd, h.kappa * (most + h.slack) + eps) << "trial " << trial;
        }
        for (const LocalPlanes::Wedge& w : m.wedges)
          EXPECT_LE(sd, w.kappa * (std::max(w.p.at(x), w.q.at(x)) + w.slack) + eps)
              << "trial " << trial;
      }
  }
  return n;
}

TEST(LocalPlanes, EveryBoundHoldsAtAShoulder) {
  // Boxes about a stepped shaft's shoulder, near the origin in double and far
  // from it in float32 (rounding crossings become slack).
  const int n = 32;
  const Vec3 far(28000, 3000, -900);
  for (const bool far_away : {false, true}) {
    const Vec3 origin = far_away ? far : Vec3::Zero();
    const Mesh shaft = sh::stepped_shaft(3, 5, 0, 10, 12, n);
    const SolidDistance s(far_away ? sh::float32(sh::translated(shaft, far)) : shaft);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    const ModelCounts counts = check_local_planes(
        s, 1.0,
        [&](std::mt19937& g) {
          const double angle = 2 * M_PI * u(g), rad = 2.6 + 0.8 * u(g);
          return Vec3(origin +
                      Vec3(rad * std::cos(angle), rad * std::sin(angle), 9.6 + 0.8 * u(g)));
        },
        rng, 200);
    EXPECT_GT(counts.wedges, 20);  // the shoulder is modelled, not only bounded by Lipschitz
    EXPECT_GT(counts.checked, 1000);
  }
}

TEST(LocalPlanes, EveryBoundHoldsAboutSmallAndLargeHoles) {
  // A board's 0.5 mm hole fits wholly within a box's reach (their normals
  // spread all round: only the facets facing the box enter its bound); a
  // plate's 5 mm bore spans many boxes.
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(0, 1);
  for (const double radius : {0.5, 5.0}) {
    const Mesh mesh = radius < 1 ? sh::plate_with_hole(2.54, 1.6, radius, 32)
                                 : sh::plate_with_hole(40, 6, radius, 64);
    const SolidDistance s(mesh);
    const ModelCounts counts = check_local_planes(
        s, radius,
        [&](std::mt19937& g) {
          const double angle = 2 * M_PI * u(g), rad = radius * (1 + 0.3 * u(g));
          return Vec3(rad * std::cos(angle), rad * std::sin(angle), 1.6 * u(g));
        },
        rng, 200);
    EXPECT_GT(counts.holes, 40) << "hole radius " << radius;
    EXPECT_GT(counts.checked, 1000) << "hole radius " << radius;
  }
}

TEST(LocalPlanes, EveryBoundHoldsBetweenNeighbouringHoles) {
  // A drilled board's row: boxes between two 0.75 mm holes 2 mm apart see
  // both within their reach; each hole is modelled on its own.
  const double pitch = 2, radius = 0.75;
  const SolidDistance s(sh::drilled_board(3, 1, pitch, 1.6, radius, 32));
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0, 1);
  const ModelCounts counts = check_local_planes(
      s, 0.25,
      [&](std::mt19937& g) {
        return Vec3(pitch * (0.5 + u(g)), pitch * (0.5 * u(g) - 0.25) + 0.5 * pitch, 1.6 * u(g));
      },
      rng, 300);
  EXPECT_GT(counts.several_holes, 8) << counts.several_holes;
  EXPECT_GT(counts.checked, 1000);
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
  const LocalPlanes m = s.local_planes(c, s.at(c).lower, 0.05);
  ASSERT_FALSE(m.supporting.empty());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (int k = 0; k < 200; ++k) {
    const Vec3 x = c + Vec3(u(rng), u(rng), u(rng));
    for (const FacePlane& q : m.supporting) EXPECT_LE(s.at(x).lower, q.at(x) + m.slack + 1e-12);
  }
}

TEST(OverlapThickness, ExactFitPinTouchesOnly) {
  const Mesh plate = sh::plate_with_hole(40, 6, 5, 32);
  const Mesh pin = sh::cylinder({0, 0}, 5, -4, 10, 32);  // the bore's own polygon
  const ThicknessResult r = overlap_thickness(SolidDistance(pin), SolidDistance(plate), 0.01);
  EXPECT_EQ(r.outcome, Outcome::kBelow);
  EXPECT_EQ(r.lower, 0.0);  // no common interior point exists
  EXPECT_LE(r.upper, 0.01);
}

TEST(OverlapThickness, BlockPushedIntoAnLBracketLegIsASlab) {
  const Mesh bracket = sh::l_bracket(40, 5, 20);  // inner corner at (5, 5)
  for (double push : {0.0, 0.3, 2.0}) {
    const Mesh block = sh::box(Vec3(5 - push, 5, 2), Vec3(25, 25, 18));
    const ThicknessResult r = overlap_thickness(SolidDistance(block), SolidDistance(bracket), 0.1);
    EXPECT_TRUE(brackets(r, push, 1e-9)) << push << ": " << r.lower << " " << r.upper;
    EXPECT_EQ(r.outcome, push > 0.1 ? Outcome::kAbove : Outcome::kBelow) << push;
  }
}

TEST(OverlapThickness, FarFromTheOriginInFloat32StaysDecided) {
  const Vec3 far(35000, 12000, -800);
  const Mesh plate = sh::float32(sh::translated(sh::plate_with_hole(40, 6, 5, 32), far));
  const Mesh pin =
      sh::float32(sh::translated(sh::prism(sh::circle({0, 0}, 5, 32, M_PI / 32), -4, 10), far));
  const SolidDistance a(pin), b(plate);
  const double exact = half_step_pin_thickness(5, 32);
  const ThicknessResult r = overlap_thickness(a, b, 0.05);
  EXPECT_EQ(r.outcome, Outcome::kBelow);
  // The float32 step (~0.002 mm here) moves the faces: the bracket holds the
  // double geometry's value up to a few steps.
  EXPECT_TRUE(brackets(r, exact, 4 * std::max(a.noise(), b.noise())))
      << r.lower << " " << exact << " " << r.upper;
}

TEST(OverlapThickness, MultiBodyBoltIsTheUnionOfItsShells) {
  // Head and shank as two closed bodies face to face (as multi-body exports
  // write them); the block overlaps both across the shared face, where the
  // largest ball (radius 1.5, centre z = 9.5) spans head and shank: no single
  // shell holds it, so the union is what is measured.
  const Mesh bolt = sh::joined(
      {sh::box(Vec3(0, 0, 10), Vec3(10, 10, 12)), sh::box(Vec3(3, 3, 0), Vec3(7, 7, 10))});
  const Mesh block = sh::box(Vec3(2, 2, 8), Vec3(8, 8, 11));
  const SolidDistance a(bolt), b(block);
  EXPECT_FALSE(a.exact());
  EXPECT_TRUE(a.closed());
  const double exact = 3.0;
  const ThicknessResult thick = overlap_thickness(a, b, 1.5);
  EXPECT_EQ(thick.outcome, Outcome::kAbove);
  EXPECT_TRUE(brackets(thick, exact, 1e-9)) << thick.lower << " " << thick.upper;
  const ThicknessResult thin = overlap_thickness(a, b, 3.5);
  EXPECT_EQ(thin.outcome, Outcome::kBelow);
  EXPECT_TRUE(brackets(thin, exact, 1e-9)) << thin.lower << " " << thin.upper;
}

TEST(OverlapThickness, AWallPenetratedBeyondAHousingsCavity) {
  // Walls 1.5 thick around a cavity (a void by the even-odd rule); the part in
  // the cavity pushes 1 mm into the top wall.
  const Mesh housing = sh::hollow_box(Vec3(0, 0, 0), Vec3(30, 20, 10), 1.5);
  const Mesh part = sh::box(Vec3(5, 5, 3), Vec3(15, 12, 9.5));
  const ThicknessResult r = overlap_thickness(SolidDistance(part), SolidDistance(housing), 0.1);
  EXPECT_EQ(r.outcome, Outcome::kAbove);
  EXPECT_TRUE(brackets(r, 1.0, 1e-9)) << r.lower << " " << r.upper;
}

TEST(OverlapThickness, AThinFoilDeepInABlockIsThinByThisMeasure) {
  // The thickness of a 0.05 mm foil 3 mm into a block is the foil's: thin. The
  // refinement's vertex guard (batch/refine.h) is what calls it a clash.
  const Mesh block = sh::box(Vec3(0, 0, 0), Vec3(20, 20, 10));
  const Mesh foil = sh::box(Vec3(5, 5, 7), Vec3(15, 5.05, 13));
  const ThicknessResult r = overlap_thickness(SolidDistance(foil), SolidDistance(block), 0.1);
  EXPECT_EQ(r.outcome, Outcome::kBelow);
  EXPECT_TRUE(brackets(r, 0.05, 1e-9)) << r.lower << " " << r.upper;
}

TEST(OverlapThickness, AnOpenShellHasNoThickness) {
  Mesh open = sh::box(Vec3(0, 0, 0), Vec3(10, 10, 10));
  open.triangles.conservativeResize(3, open.triangles.cols() - 2);  // one side missing
  const SolidDistance a(open);
  EXPECT_FALSE(a.closed());
  const ThicknessResult r =
      overlap_thickness(a, SolidDistance(sh::box(Vec3(5, 5, 5), Vec3(15, 15, 15))), 0.1, 8.0);
  EXPECT_EQ(r.outcome, Outcome::kNoInside);
  EXPECT_EQ(r.upper, 8.0);
}

}  // namespace
}  // namespace pd

namespace pd {
namespace {

TEST(SurfaceDepth, NeverBelowTheDeepestVertexWhateverTheBudget) {
  namespace sh = shapes;
  const std::pair<Mesh, Mesh> cases[] = {
      {sh::box(Vec3(5, 5, 7), Vec3(15, 5.05, 13)), sh::box(Vec3(0, 0, 0), Vec3(20, 20, 10))},
      {sh::cylinder({0, 0}, 5.3, -4, 10, 32), sh::plate_with_hole(40, 6, 5, 32)},
      {sh::box(Vec3(3, 3, 3), Vec3(20, 12, 9.5)),
       sh::hollow_box(Vec3(0, 0, 0), Vec3(30, 20, 10), 1.5)}};
  for (const auto& [a, b] : cases) {
    const SolidDistance sa(a), sb(b);
    const MeshDepthBound vertex = deepest_vertex_depth(sa.mesh(), sb.mesh());
    ASSERT_GT(vertex.depth, 0.0);
    for (long budget : {0L, 100L, 20000L}) {
      const double surface = std::max(surface_depth(sa.mesh(), sb, budget).depth,
                                      surface_depth(sb.mesh(), sa, budget).depth);
      EXPECT_GE(surface, vertex.depth - 1e-12) << budget;
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

}  // namespace
}  // namespace pd
