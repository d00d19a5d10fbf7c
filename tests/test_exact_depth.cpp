// The default method against the exact reference (issue 29), a story across
// methods, epa and the exact step: near-degenerate pairs — touching, coplanar,
// 1e-9 and 1e-12 offsets, rotated, float32 far from the origin, flat parts, the
// hard cases — within 1e-9 relative, with no floor but the contact rounding
// below which pdcheck reports 0 (kGapRounding of the pair's scale,
// docs/numerics.md). The reference itself: test_exact_reference.cpp; the exact
// step: test_exact_facet.cpp, test_exact_hull_depth.cpp.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdio>

#include "box_points.h"
#include "corpus/exact_reference.h"
#include "corpus/generators.h"
#include "geometry/frame.h"
#include "random_rotation.h"
#include "solve/epa.h"
#include "solve/methods.h"
#include "tolerances.h"

using namespace pd;

using pd_test::box_points;

namespace {

using pd_test::random_rotation;

// b's lowest x at 1 − eps (a is the unit cube), moved by (0, y, z).
Points against(const Points& b, double eps, double y, double z) {
  return (b.colwise() + Vec3(1 - eps - b.row(0).minCoeff(), y, z)).eval();
}

struct Tally {
  int pairs = 0, exact_step = 0;
};

// The default method's depth against the exact reference: within 1e-9
// relative, or both at or below the contact rounding (reported 0 by rule).
void expect_default_exact(const std::string& what, const Points& a, const Points& b, Tally& t) {
  static IpoptLocalSolver ipopt;
  const DepthSolution m = solve_convex_pair(a, b, SolverSettings{}, ipopt);
  const testgen::ExactReference e = testgen::exact_reference_depth(a, b);
  const double contact = tol::kGapRounding * pair_frame(a, b).scale;
  char text[240];
  std::snprintf(text, sizeof text, "%s: exact %.17g, default %.17g (%s)", what.c_str(), e.depth,
                m.depth, stop_reason_name(m.stats.stop_reason));
  SCOPED_TRACE(text);
  EXPECT_TRUE(m.fallback.empty()) << m.fallback;
  if (m.depth > contact || e.depth > contact) {
    EXPECT_LE(std::abs(m.depth - e.depth), 1e-9 * e.depth);
  }
  ++t.pairs;
  const PairProblem pr(a, b);
  t.exact_step += !epa_bracket(pr, tol::kEpaMaxIterations).near_faces.empty();
}

testgen::PairCase posed(SphereSampler& r, const testgen::PairCase& c, double far, bool f32) {
  const Eigen::Matrix3d rot = random_rotation(r);
  const Vec3 shift = far * r.direction();
  testgen::PairCase out = c;
  for (Points* x : {&out.a, &out.b}) {
    *x = (rot * *x).colwise() + shift;
    if (f32) *x = x->cast<float>().cast<double>();
  }
  return out;
}

}  // namespace

TEST(ExactFacet, DefaultIsExactOnNearDegeneratePairs) {
  // Boxes face on face, edge on face, corner on face and coplanar, overlapping
  // or apart by 0, 1e-12, 1e-9 or 1e-6; at the origin and far from it, rotated,
  // in double and float32.
  SphereSampler r(1e9);
  Tally t;
  const Points a = box_points(Vec3::Zero(), Vec3::Ones());
  const Eigen::Matrix3d tilt = Eigen::AngleAxisd(M_PI / 4, Vec3::UnitY()).toRotationMatrix();
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.6, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  for (double eps : {0.0, 1e-12, -1e-12, 1e-9, -1e-9, 1e-6}) {
    const std::string e = " eps " + std::to_string(eps);
    const std::vector<std::pair<std::string, testgen::PairCase>> family = {
        {"face" + e, {a, against(box_points(Vec3::Zero(), Vec3(1, 0.5, 0.7)), eps, 0.2, 0.1)}},
        {"coplanar" + e, {a, against(a, eps, 0, 0)}},
        {"edge" + e, {a, against(tilt * a, eps, 0.1, 0.1)}},
        {"corner" + e, {a, against(turn * a, eps, 0.3, 0.3)}}};
    for (const auto& [name, c] : family) {
      expect_default_exact(name, c.a, c.b, t);
      for (double far : {0.0, 20000.0})
        for (bool f32 : {false, true}) {
          const testgen::PairCase p = posed(r, c, far, f32);
          expect_default_exact(name + " far " + std::to_string(far) + (f32 ? " f32" : ""), p.a, p.b,
                               t);
        }
    }
  }
  RecordProperty("exact_steps", t.exact_step);
  EXPECT_GT(t.exact_step, t.pairs / 4);
}

TEST(ExactFacet, DefaultIsExactOnFlatPartsAndHardCases) {
  SphereSampler r(3);
  Tally t;
  const Points cube = box_points(Vec3::Zero(), Vec3::Ones());
  for (double eps : {1e-9, 1e-12}) {
    // A square just inside the cube's top face: depth eps (push it up).
    Points square(3, 4);
    square << 0.2, 0.8, 0.8, 0.2, 0.2, 0.2, 0.8, 0.8, 1 - eps, 1 - eps, 1 - eps, 1 - eps;
    for (int k = 0; k < 4; ++k) {
      const Eigen::Matrix3d rot = k ? random_rotation(r) : Eigen::Matrix3d::Identity();
      expect_default_exact("square eps " + std::to_string(eps), rot * cube, rot * square, t);
    }
  }
  for (int k = 0; k < 32; ++k) {
    const testgen::PairCase c = testgen::hard_case(r, k);
    expect_default_exact("hard case " + std::to_string(k), c.a, c.b, t);
  }
  EXPECT_GT(t.exact_step, 0);
}
