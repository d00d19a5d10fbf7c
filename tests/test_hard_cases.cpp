// The hard cases: geometry on which convex penetration-depth codes are known to
// return wrong or NaN depths. Each case runs through the whole pair check (hulls,
// solve, classification) for `mlsl` and for `exact`, and is checked against an
// analytic depth where one exists, else against `exact`, with the stated tolerance.
#include <gtest/gtest.h>

#include <cmath>

#include "batch/pair_solve.h"
#include "box_points.h"
#include "bracket_check.h"
#include "corpus/generators.h"
#include "inline_part.h"
#include "solve/methods.h"

using namespace pd;
using pd_test::inline_part;

using pd_test::box_points;

namespace {

Points shifted(Points p, const Vec3& d) {
  p.colwise() += d;
  return p;
}

Points points(std::initializer_list<Vec3> l) {
  Points p(3, static_cast<Eigen::Index>(l.size()));
  int k = 0;
  for (const Vec3& v : l) p.col(k++) = v;
  return p;
}

PairResult check(const Points& a, const Points& b, Method m, double tolerance) {
  static IpoptLocalSolver ipopt;
  SolverSettings s;
  s.method = m;
  return solve_part_pair(0, inline_part("a", a), 1, inline_part("b", b), s, tolerance, ipopt);
}

double gap_world(const Points& a, const Points& b, const Vec3& v) {
  return (v.transpose() * a).maxCoeff() - (v.transpose() * b).minCoeff();
}

/// Both methods: no NaN, the expected status, the depth within `abs_tol` of the
/// expected one, and a direction that achieves the depth (when it is positive).
void expect_case(const std::string& what, const Points& a, const Points& b, double expected,
                 double abs_tol, Status status, double tolerance = 0.1) {
  pd::testing::expect_bracket_holds(what, a, b);
  for (Method m : {Method::kExact, Method::kMlsl}) {
    const PairResult r = check(a, b, m, tolerance);
    SCOPED_TRACE(what + " / " + method_name(m));
    ASSERT_NE(r.status, Status::kError) << r.error;
    ASSERT_TRUE(std::isfinite(r.depth));
    ASSERT_TRUE(r.direction.allFinite());
    EXPECT_NEAR(r.direction.norm(), 1.0, 1e-12);
    EXPECT_NEAR(r.depth, expected, abs_tol);
    EXPECT_EQ(status_name(r.status), std::string(status_name(status)));
    EXPECT_TRUE(r.fallback.empty()) << r.fallback;
    if (r.depth > 0) {
      EXPECT_NEAR(gap_world(a, b, r.direction), r.depth, abs_tol);
    }
  }
}

/// No analytic value: mlsl must equal exact within 1e-9 relative.
void expect_mlsl_equals_exact(const std::string& what, const Points& a, const Points& b) {
  pd::testing::expect_bracket_holds(what, a, b);
  const PairResult e = check(a, b, Method::kExact, 0.1), m = check(a, b, Method::kMlsl, 0.1);
  SCOPED_TRACE(what);
  ASSERT_NE(m.status, Status::kError) << m.error;
  ASSERT_TRUE(std::isfinite(m.depth) && m.direction.allFinite());
  EXPECT_NEAR(m.depth, e.depth, 1e-9 * std::max(e.depth, 1e-300));
  EXPECT_EQ(m.status, e.status);
  EXPECT_NEAR(gap_world(a, b, m.direction), m.depth, 1e-9 * std::max(e.depth, 1e-12));
}

const Vec3 kO = Vec3::Zero(), kOne = Vec3::Ones();

}  // namespace

TEST(HardCases, TouchingFaceFace) {
  const Points a = box_points(kO, kOne);
  for (double eps : {0.0, 1e-12, -1e-12}) {  // of the size (the pair spans 2 along x)
    const Points b = box_points(Vec3(1 - 2 * eps, 0, 0), Vec3(2 - 2 * eps, 1, 1));
    expect_case("face-face eps " + std::to_string(eps), a, b, std::max(0.0, 2 * eps), 1e-14,
                Status::kSeparated);
  }
}

TEST(HardCases, TouchingEdgeEdge) {
  // A tetrahedron's top edge along x, another's bottom edge along y, meeting at 0.
  const Points a = points({{-1, 0, 0}, {1, 0, 0}, {0, -1, -1}, {0, 1, -1}});
  for (double eps : {0.0, 1e-12, -1e-12}) {
    const Points b =
        shifted(points({{0, -1, 0}, {0, 1, 0}, {-1, 0, 1}, {1, 0, 1}}), Vec3(0, 0, -2 * eps));
    expect_case("edge-edge eps " + std::to_string(eps), a, b, std::max(0.0, 2 * eps), 1e-14,
                Status::kSeparated);
  }
}

TEST(HardCases, TouchingVertexFace) {
  const Points a = box_points(Vec3(-1, -1, -1), Vec3(1, 1, 0));
  for (double eps : {0.0, 1e-12, -1e-12}) {
    const Points b =
        shifted(points({{0, 0, 0}, {1, 0, 2}, {-1, 1, 2}, {-1, -1, 2}}), Vec3(0, 0, -3 * eps));
    expect_case("vertex-face eps " + std::to_string(eps), a, b, std::max(0.0, 3 * eps), 1e-14,
                Status::kSeparated);
  }
}

namespace {

enum class Touch { kBoxEdgeOnFace, kBoxEdgeOnEdge, kEdgeEdge, kVertexFace, kPolytopeEdgeOnFace };

const char* touch_name(Touch t) {
  switch (t) {
    case Touch::kBoxEdgeOnFace:
      return "box edge on face";
    case Touch::kBoxEdgeOnEdge:
      return "box edge on edge";
    case Touch::kEdgeEdge:
      return "edge across edge";
    case Touch::kVertexFace:
      return "vertex on face";
    case Touch::kPolytopeEdgeOnFace:
      return "polytope edge on face";
  }
  return "";
}

/// n random points of the slab lo <= z <= hi over [-w, w]².
Points slab_points(SphereSampler& r, int n, double w, double lo, double hi) {
  Points p(3, n);
  for (int i = 0; i < n; ++i)
    p.col(i) =
        Vec3(w * (2 * r.uniform() - 1), w * (2 * r.uniform() - 1), lo + (hi - lo) * r.uniform());
  return p;
}

Points joined(const Points& a, const Points& b) {
  Points p(3, a.cols() + b.cols());
  p << a, b;
  return p;
}

/// Two convex polytopes touching at z = 0 (a below, b above) along the feature
/// `t`, in their own frame: the contact is exact there (every touching vertex
/// has z = 0, every other of b has z > 0 and of a z < 0).
testgen::PairCase touching_pair(SphereSampler& r, Touch t) {
  const double w = 1 + 4 * r.uniform();
  const Points a_box = box_points(Vec3(-w, -w, -1 - r.uniform()), Vec3(w, w, 0));
  switch (t) {
    case Touch::kBoxEdgeOnFace:
    case Touch::kBoxEdgeOnEdge: {
      // A box tilted by θ about its lowest edge, which lies along x at z = 0.
      const double th = 0.1 + 1.3 * r.uniform(), s1 = 0.5 + r.uniform(), s2 = 0.5 + r.uniform();
      const double y0 = t == Touch::kBoxEdgeOnEdge ? w : w * (1.6 * r.uniform() - 0.8);
      const double x0 = -w * r.uniform(), x1 = w * r.uniform() + 0.1;
      const Vec3 e1(0, std::cos(th), std::sin(th)), e2(0, -std::sin(th), std::cos(th));
      Points b(3, 8);
      for (int k = 0; k < 8; ++k)
        b.col(k) = Vec3(k & 1 ? x1 : x0, y0, 0) + (k & 2 ? s1 : 0.0) * e1 + (k & 4 ? s2 : 0.0) * e2;
      return {a_box, b};
    }
    case Touch::kEdgeEdge: {
      // a's top edge and b's bottom edge cross at the origin.
      const double p0 = M_PI * r.uniform(), p1 = p0 + 0.3 + 2.5 * r.uniform();
      const Vec3 d0(std::cos(p0), std::sin(p0), 0), d1(std::cos(p1), std::sin(p1), 0);
      Points ea(3, 2), eb(3, 2);
      ea << w * d0, -w * d0;
      eb << w * d1, -w * d1;
      return {joined(ea, slab_points(r, 6, w, -w, -0.1 * w)),
              joined(eb, slab_points(r, 6, w, 0.1 * w, w))};
    }
    case Touch::kVertexFace: {
      Points v(3, 1);
      v.col(0) = Vec3(0.8 * w * (2 * r.uniform() - 1), 0.8 * w * (2 * r.uniform() - 1), 0);
      return {a_box, joined(v, (slab_points(r, 7, 0.5, 0.2, 1.5).colwise() + v.col(0)).eval())};
    }
    case Touch::kPolytopeEdgeOnFace: {
      Points e(3, 2);
      const double p0 = M_PI * r.uniform();
      e << 0.5 * w * Vec3(std::cos(p0), std::sin(p0), 0),
          -0.5 * w * Vec3(std::cos(p0), std::sin(p0), 0);
      return {a_box, joined(e, slab_points(r, 10, w, 0.05 * w, w))};
    }
  }
  return {};
}

/// The pair moved rigidly: a random rotation, then an offset of `far` in a
/// random direction.
testgen::PairCase posed(SphereSampler& r, testgen::PairCase c, double far) {
  const Eigen::Matrix3d rot =
      Eigen::AngleAxisd(2 * M_PI * r.uniform(), r.direction()).toRotationMatrix();
  const Vec3 shift = far * r.direction();
  c.a = (rot * c.a).colwise() + shift;
  c.b = (rot * c.b).colwise() + shift;
  return c;
}

}  // namespace

// Touching along an edge, a vertex or a face at random poses: where the exact
// reference says 0, mlsl says exactly 0 too (it used to stop at a fitted facet
// or a first local facet within kTouch and keep its gap as the depth), and
// elsewhere (rounding tipped the pair into overlap) it is within the
// scale-relative floor of 1e-12 · L. Far from the origin the input's own
// rounding (~1e-12 of the frame) makes the touching faces facets of their own,
// some a hair apart, some overlapping: there the floor is the measure.
TEST(HardCases, TouchingPairsAtRandomPosesGiveTheExactDepth) {
  SphereSampler r(2025);
  int exact_zero = 0, cases = 0;
  for (Touch t : {Touch::kBoxEdgeOnFace, Touch::kBoxEdgeOnEdge, Touch::kEdgeEdge,
                  Touch::kVertexFace, Touch::kPolytopeEdgeOnFace})
    for (double far : {0.0, 30.0, 2000.0, 35000.0})
      for (int k = 0; k < 12; ++k) {
        const testgen::PairCase c = posed(r, touching_pair(r, t), far);
        pd::testing::expect_bracket_holds(touch_name(t), c.a, c.b);
        const PairResult e = check(c.a, c.b, Method::kExact, 0.01);
        const PairResult m = check(c.a, c.b, Method::kMlsl, 0.01);
        const double floor = 1e-12 * pair_size(inline_part("a", c.a), inline_part("b", c.b));
        SCOPED_TRACE(std::string(touch_name(t)) + " far " + std::to_string(far) + " case " +
                     std::to_string(k) + ": exact " + std::to_string(e.depth * 1e15) +
                     "e-15 mlsl " + std::to_string(m.depth * 1e15) + "e-15 (" +
                     stop_reason_name(m.stats.stop_reason) + ")");
        ASSERT_NE(m.status, Status::kError) << m.error;
        EXPECT_EQ(m.status, Status::kSeparated);
        EXPECT_TRUE(m.fallback.empty()) << m.fallback;
        EXPECT_LE(std::abs(m.depth - e.depth), floor);
        if (e.depth == 0 && far < 100) {
          ++exact_zero;
          EXPECT_EQ(m.depth, 0.0);
        }
        ++cases;
      }
  EXPECT_EQ(cases, 5 * 4 * 12);
  EXPECT_GE(exact_zero, cases / 4);  // most near the origin: a real share
}

// The same families as a mesh file gives them: posed, then every coordinate
// rounded to float32 (assimp's storage). Rounding moves the touching faces
// apart or into each other by ~1e-7 of the coordinates, so the exact depth is
// 0 or a rounding-sized overlap; mlsl must agree with it to the same
// scale-relative floor, and give exactly 0 wherever the exact reference does.
TEST(HardCases, TouchingFloat32PairsAtRandomPosesGiveTheExactDepth) {
  SphereSampler r(2026);
  int exact_zero = 0, overlapping = 0, cases = 0;
  for (Touch t : {Touch::kBoxEdgeOnFace, Touch::kBoxEdgeOnEdge, Touch::kEdgeEdge,
                  Touch::kVertexFace, Touch::kPolytopeEdgeOnFace})
    for (double far : {0.0, 30.0, 2000.0, 35000.0})
      for (int k = 0; k < 12; ++k) {
        testgen::PairCase c = posed(r, touching_pair(r, t), far);
        c.a = c.a.cast<float>().cast<double>();
        c.b = c.b.cast<float>().cast<double>();
        const PairResult e = check(c.a, c.b, Method::kExact, 0.01);
        const PairResult m = check(c.a, c.b, Method::kMlsl, 0.01);
        const double floor = 1e-12 * pair_size(inline_part("a", c.a), inline_part("b", c.b));
        SCOPED_TRACE(std::string(touch_name(t)) + " far " + std::to_string(far) + " case " +
                     std::to_string(k) + ": exact " + std::to_string(e.depth * 1e15) +
                     "e-15 mlsl " + std::to_string(m.depth * 1e15) + "e-15 (" +
                     stop_reason_name(m.stats.stop_reason) + ")");
        ASSERT_NE(m.status, Status::kError) << m.error;
        EXPECT_EQ(m.status, e.status);
        EXPECT_TRUE(m.fallback.empty()) << m.fallback;
        EXPECT_LE(std::abs(m.depth - e.depth), floor);
        if (e.depth == 0) {
          ++exact_zero;
          EXPECT_EQ(m.depth, 0.0);
        } else {
          ++overlapping;
        }
        ++cases;
      }
  EXPECT_EQ(cases, 5 * 4 * 12);
  RecordProperty("exact_zero", exact_zero);
  RecordProperty("overlapping", overlapping);
  // Both outcomes of the rounding are exercised.
  EXPECT_GE(exact_zero, cases / 10);
  EXPECT_GE(overlapping, cases / 10);
}

TEST(HardCases, OverlapOfOneBillionthOfTheSize) {
  const Points a = box_points(kO, kOne), b = box_points(Vec3(1 - 2e-9, 0, 0), Vec3(2 - 2e-9, 1, 1));
  expect_case("overlap 1e-9", a, b, 2e-9, 1e-15, Status::kFalsePositive);
}

TEST(HardCases, CoplanarFacesWithTiedOptima) {
  // Top and bottom faces coplanar; moving along +x or +y both need 0.5.
  const Points a = box_points(kO, kOne), b = box_points(Vec3(0.5, 0.5, 0), Vec3(1.5, 1.5, 1));
  expect_case("coplanar", a, b, 0.5, 1e-12, Status::kInterference);
}

TEST(HardCases, IdenticalPolytopes) {
  expect_case("identical cubes", box_points(kO, kOne), box_points(kO, kOne), 1.0, 1e-12,
              Status::kInterference);
  SphereSampler r(77);
  const Points p = testgen::ball_polytope(r, 40, Vec3(3, 4, 5), 10);
  expect_mlsl_equals_exact("identical random", p, p);
}

TEST(HardCases, OneStrictlyInsideTheOther) {
  expect_case("inside", box_points(kO, kOne), box_points(Vec3::Constant(0.4), Vec3::Constant(0.6)),
              0.6, 1e-12, Status::kInterference);
}

TEST(HardCases, OptimumAtThePolesAndTheWrapAround) {
  const Points a = box_points(-kOne, kOne);  // libccd's 2x2x2 cube, shifted 1.9 each way
  const Vec3 axes[] = {Vec3::UnitZ(), -Vec3::UnitZ(), Vec3::UnitX(), -Vec3::UnitX()};
  for (const Vec3& d : axes) {
    const Points b = shifted(a, 1.9 * d);
    expect_case("axis", a, b, 0.1, 1e-12, Status::kFalsePositive, 0.2);
    const PairResult m = check(a, b, Method::kMlsl, 0.2);
    EXPECT_NEAR(m.direction.dot(d), 1.0, 1e-12);
  }
}

TEST(HardCases, ThinPlates) {
  const Points a = box_points(kO, Vec3(1000, 1000, 1)),
               b = box_points(Vec3(0, 0, 0.99), Vec3(1000, 1000, 1.99));
  expect_case("plates 1000x1000x1", a, b, 0.01, 1e-9, Status::kFalsePositive, 0.05);
  // Thickness 1e-6 of the size, overlapping by half of it, rotated off the axes.
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Points c = rot * box_points(kO, Vec3(1000, 1000, 1e-3));
  const Points d = rot * box_points(Vec3(100, 100, 0.5e-3), Vec3(900, 900, 1.5e-3));
  expect_case("plates 1e-6", c, d, 0.5e-3, 1e-12, Status::kFalsePositive, 0.01);
}

TEST(HardCases, NeedlesAndSlivers) {
  const Points a = box_points(kO, Vec3(100, 0.01, 0.01));
  const Points b = box_points(Vec3(50, -50, 0.005), Vec3(50.01, 50, 0.015));
  expect_case("crossed needles", a, b, 0.005, 1e-12, Status::kFalsePositive);
  // A sliver tetrahedron (height 1e-4 of its size) through a box corner.
  const Points s = points({{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {3, 3, 1e-3}});
  expect_mlsl_equals_exact("sliver", s, shifted(box_points(kO, kOne), Vec3(2, 2, -0.5)));
}

TEST(HardCases, DuplicateAndNearDuplicateVertices) {
  // An unwelded STL: every vertex three times, two copies off by 1e-13.
  const Points clean = box_points(kO, kOne);
  Points dup(3, 24);
  for (int k = 0; k < 8; ++k) {
    dup.col(3 * k) = clean.col(k);
    dup.col(3 * k + 1) = clean.col(k);
    dup.col(3 * k + 2) = clean.col(k) + Vec3(1e-13, -1e-13, 1e-13);
  }
  const Points b = box_points(Vec3(0.7, 0.2, 0.2), Vec3(1.7, 0.8, 0.8));
  expect_case("duplicates", dup, b, 0.3, 1e-12, Status::kInterference);
}

TEST(HardCases, FlatAndCollinearInput) {
  const Points cube = box_points(kO, kOne);
  const Points square =
      points({{0.2, 0.2, 0.5}, {0.8, 0.2, 0.5}, {0.8, 0.8, 0.5}, {0.2, 0.8, 0.5}});
  expect_case("flat square in a cube", cube, square, 0.5, 1e-12, Status::kInterference);
  const Points segment = points({{0.2, 0.5, 0.3}, {0.5, 0.5, 0.3}, {0.8, 0.5, 0.3}});
  expect_case("collinear segment in a cube", cube, segment, 0.3, 1e-12, Status::kInterference);
}

TEST(HardCases, FarFromTheOriginWithASmallInterference) {
  // x ≈ 35,000 mm, 0.01 mm of interference: double coordinates keep it to ~1e-11.
  const Points a = box_points(Vec3(35000, 0, 0), Vec3(35010, 10, 10));
  const Points b = box_points(Vec3(35009.99, 2, 2), Vec3(35020, 8, 8));
  expect_case("x=35000 tol 0.005", a, b, 0.01, 1e-9, Status::kInterference, 0.005);
  expect_case("x=35000 tol 0.02", a, b, 0.01, 1e-9, Status::kFalsePositive, 0.02);
}

TEST(HardCases, TinyParts) {
  // 1e-3 mm parts overlapping by 1e-5 mm: the unit frame makes size irrelevant.
  const Points a = box_points(kO, Vec3::Constant(1e-3)),
               b = box_points(Vec3(0.99e-3, 0, 0), Vec3(2e-3, 1e-3, 1e-3));
  expect_case("tiny", a, b, 1e-5, 1e-17, Status::kInterference, 1e-6);
}

TEST(HardCases, PinAgainstATenMetrePanel) {
  // A 1 mm pin (24-gon prism) standing 0.1 mm deep in a 10 m panel.
  Points pin(3, 48);
  for (int k = 0; k < 24; ++k) {
    const double t = 2 * M_PI * k / 24;
    pin.col(k) = Vec3(5000 + 0.5 * std::cos(t), 5000 + 0.5 * std::sin(t), 4.9);
    pin.col(24 + k) = Vec3(5000 + 0.5 * std::cos(t), 5000 + 0.5 * std::sin(t), 24.9);
  }
  const Points panel = box_points(kO, Vec3(10000, 10000, 5));
  expect_case("pin", panel, pin, 0.1, 1e-9, Status::kFalsePositive, 0.2);
}

TEST(HardCases, TwoThousandVerticesPerPart) {
  SphereSampler r(2000);
  const Points a = testgen::ellipsoid_polytope(r, 2000, kO, 50);
  const Points b = testgen::ellipsoid_polytope(r, 2000, Vec3(30, 20, 10), 40);
  expect_mlsl_equals_exact("2000+2000", a, b);
}
