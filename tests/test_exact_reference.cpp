// The exact rational reference (corpus/exact_reference.h), the yardstick of
// the exact depth tests: the input's own depths on axis-aligned boxes, the
// double hull's away from contact.
#include <gtest/gtest.h>

#include "box_points.h"
#include "corpus/exact_reference.h"
#include "corpus/generators.h"
#include "geometry/frame.h"
#include "solve/methods.h"
#include "tolerances.h"

using namespace pd;
using pd_test::box_points;

TEST(ExactReference, AxisAlignedDepthsAreTheInputsOwn) {
  // Overlaps of 1e-9 and 1e-12 along x: the depth is 1 − fl(1 − eps), exactly
  // (Sterbenz), not eps; touching and apart boxes have depth 0.
  const Points a = box_points(Vec3::Zero(), Vec3::Ones());
  for (double eps : {1e-9, 1e-12, 1e-15}) {
    const Points b = box_points(Vec3(1 - eps, 0, 0), Vec3(2 - eps, 1, 1));
    const testgen::ExactReference e = testgen::exact_reference_depth(a, b);
    EXPECT_EQ(e.depth, 1.0 - (1.0 - eps)) << eps;
    EXPECT_TRUE(e.all_points);
    EXPECT_NEAR(std::abs(e.direction.x()), 1.0, 1e-15);
  }
  EXPECT_EQ(testgen::exact_reference_depth(a, box_points(Vec3(1, 0, 0), Vec3(2, 1, 1))).depth, 0.0);
  EXPECT_EQ(testgen::exact_reference_depth(a, box_points(Vec3(1.5, 0, 0), Vec3(2, 1, 1))).depth,
            0.0);
  EXPECT_EQ(testgen::exact_reference_depth(a, a).depth, 1.0);
  // Thin plates overlapping by 0.01 (1000 × 1000 × 1): the z facet.
  const Points p = box_points(Vec3::Zero(), Vec3(1000, 1000, 1));
  const Points q = box_points(Vec3(0, 0, 0.99), Vec3(1000, 1000, 1.99));
  EXPECT_EQ(testgen::exact_reference_depth(p, q).depth, 1.0 - 0.99);
}

TEST(ExactReference, AgreesWithTheDoubleHullAwayFromContact) {
  SphereSampler r(7);
  IpoptLocalSolver ipopt;
  SolverSettings exact;
  exact.method = Method::kExact;
  for (int k = 0; k < 10; ++k) {
    const testgen::PairCase c = testgen::vertex_class(r, 12);
    const double hull = solve_convex_pair(c.a, c.b, exact, ipopt).depth;
    EXPECT_NEAR(testgen::exact_reference_depth(c.a, c.b).depth, hull,
                tol::kGapRounding * pair_frame(c.a, c.b).scale);
  }
}
