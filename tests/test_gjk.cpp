// GJK on the Minkowski difference (solve/gjk.h): apart pairs separated by a
// direction of gap <= 0, overlapping ones enclosed by a tetrahedron around the
// origin, touching ones separated at a gap of about 0.
#include <gtest/gtest.h>

#include "box_points.h"
#include "corpus/contacts.h"
#include "corpus/generators.h"
#include "solve/gjk.h"
#include "tolerances.h"

using namespace pd;

TEST(Gjk, SeparatesApartPairsAndEnclosesOverlappingOnes) {
  SphereSampler r(5);
  for (int k = 0; k < 20; ++k) {
    const testgen::PairCase apart = testgen::apart_boxes_overlapping(r, 30);
    const PairProblem pa(apart.a, apart.b);
    const GjkResult ga = gjk_enclose_origin(pa, tol::kGjkMaxIterations);
    EXPECT_EQ(ga.outcome, GjkResult::Outcome::kSeparated);
    EXPECT_LE(pa.gap(ga.direction), 0.0);
    const testgen::PairCase over = testgen::vertex_class(r, 30);
    const PairProblem po(over.a, over.b);
    const GjkResult go = gjk_enclose_origin(po, tol::kGjkMaxIterations);
    ASSERT_EQ(go.outcome, GjkResult::Outcome::kEnclosed);
    // The origin is inside the tetrahedron: a convex combination with weights > 0.
    Eigen::Matrix4d m;
    for (int c = 0; c < 4; ++c) m.col(c) << go.tetrahedron[c], 1.0;
    const Eigen::Vector4d w = m.fullPivLu().solve(Eigen::Vector4d(0, 0, 0, 1));
    EXPECT_GT(w.minCoeff(), 0.0);
  }
}

TEST(Gjk, TouchingAndApartBoxesAreDecided) {
  // Unit cubes face on face, then moved apart by 1 along x. Apart: a direction
  // of gap <= 0, with the lower bound below it. Touching: the origin lies on
  // D's boundary, so either a supporting plane through it (gap 0 to rounding)
  // or a tetrahedron holding it (on a face, to rounding); never undecided.
  const Points a = pd_test::box_points(Vec3::Zero(), Vec3::Ones());
  for (double gap : {0.0, 1.0}) {
    SCOPED_TRACE("apart by " + std::to_string(gap));
    const Points b = pd_test::box_points(Vec3(1 + gap, 0.2, 0.1), Vec3(2 + gap, 0.7, 0.8));
    const PairProblem pr(a, b);
    const GjkResult g = gjk_enclose_origin(pr, tol::kGjkMaxIterations);
    ASSERT_NE(g.outcome, GjkResult::Outcome::kUndecided);
    if (gap > 0) {
      ASSERT_EQ(g.outcome, GjkResult::Outcome::kSeparated);
    }
    if (g.outcome == GjkResult::Outcome::kSeparated) {
      EXPECT_NEAR(g.direction.norm(), 1.0, 1e-12);
      EXPECT_NEAR(pr.gap(g.direction), g.gap, 1e-15);
      EXPECT_LE(g.gap, gap > 0 ? 0.0 : tol::kEpaRounding);
      EXPECT_GE(g.gap, gap > 0 ? g.lower : -tol::kEpaRounding);
      EXPECT_LE(g.lower, g.gap);
    } else {
      Eigen::Matrix4d m;
      for (int c = 0; c < 4; ++c) m.col(c) << g.tetrahedron[c], 1.0;
      const Eigen::Vector4d w = m.fullPivLu().solve(Eigen::Vector4d(0, 0, 0, 1));
      EXPECT_GE(w.minCoeff(), -1e-12);
      EXPECT_LE(w.minCoeff(), 1e-9);  // on a face: the boxes only touch
    }
  }
}
