// The exact facet step (solve/exact_facet.h) on its own: axis-aligned boxes
// overlapping by 1e-9 and 1e-12, whose near faces lie exactly on the input's
// planes, so the step must prove the depth and give the exact reference's to
// one rounding; without faces it proves nothing.
#include <gtest/gtest.h>

#include "box_points.h"
#include "corpus/exact_reference.h"
#include "solve/epa.h"
#include "solve/exact_facet.h"
#include "tolerances.h"

using namespace pd;
using pd_test::box_points;

TEST(ExactFacet, AxisAlignedOverlapsAreProvedByTheNearFaces) {
  const Points a = box_points(Vec3::Zero(), Vec3::Ones());
  for (double eps : {1e-9, 1e-12}) {
    SCOPED_TRACE("eps " + std::to_string(eps));
    const Points b = box_points(Vec3(1 - eps, 0.2, 0.1), Vec3(2 - eps, 0.7, 0.8));
    const PairProblem pr(a, b);
    const DepthBracket br = epa_bracket(pr, tol::kEpaMaxIterations);
    ASSERT_TRUE(br.certified());
    ASSERT_FALSE(br.near_faces.empty());
    const double bound = (br.nearest_low + 2 * tol::kEpaRounding) * pr.frame().scale;
    const auto f = exact_facet_depth(a, b, br.near_faces, bound);
    ASSERT_TRUE(f.has_value());
    const double truth = testgen::exact_reference_depth(a, b).depth;
    EXPECT_EQ(truth, 1.0 - (1.0 - eps));
    EXPECT_NEAR(f->depth, truth, 4e-16 * truth);
    EXPECT_NEAR(std::abs(f->direction.x()), 1.0, 1e-12);
    // No faces: nothing to prove the depth with.
    EXPECT_FALSE(exact_facet_depth(a, b, {}, bound).has_value());
  }
}
