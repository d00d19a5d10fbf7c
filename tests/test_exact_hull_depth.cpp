// The exact step of a closed EPA bracket (solve/exact_hull_depth.h) against
// the exact reference: rotated cubes overlapping by 1e-9 and 1e-12, whose
// bracket closes to kEpaBracket only.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "box_points.h"
#include "corpus/exact_reference.h"
#include "corpus/generators.h"
#include "random_rotation.h"
#include "solve/epa.h"
#include "solve/exact_facet.h"
#include "solve/exact_hull_depth.h"
#include "tolerances.h"

using namespace pd;

using pd_test::box_points;

namespace {

using pd_test::random_rotation;

}  // namespace

TEST(ExactFacet, RotatedTinyOverlapsAreRecomputedExactly) {
  // Rotated unit cubes overlapping by 1e-9 and 1e-12: the bracket closes to
  // kEpaBracket only, and its exact step must give the exact reference's depth
  // to one rounding.
  SphereSampler r(291);
  int by_faces = 0;
  for (double eps : {1e-9, 1e-12})
    for (int k = 0; k < 6; ++k) {
      const Eigen::Matrix3d rot = random_rotation(r);
      const Points a = rot * box_points(Vec3::Zero(), Vec3::Ones());
      const Points b = rot * box_points(Vec3(1 - eps, 0.2, 0.1), Vec3(2 - eps, 0.7, 0.8));
      const PairProblem pr(a, b);
      const DepthBracket br = epa_bracket(pr, tol::kEpaMaxIterations);
      const double truth = testgen::exact_reference_depth(a, b).depth;
      SCOPED_TRACE("eps " + std::to_string(eps) + " #" + std::to_string(k));
      ASSERT_TRUE(br.certified());
      ASSERT_FALSE(br.near_faces.empty());
      by_faces += exact_facet_depth(a, b, br.near_faces,
                                    (br.nearest_low + 2 * tol::kEpaRounding) * pr.frame().scale)
                      .has_value();
      const auto e = exact_bracket_depth(a, b, br, pr.frame().scale);
      ASSERT_TRUE(e.has_value());
      EXPECT_NEAR(e->depth, truth, 4e-16 * truth);
      EXPECT_NEAR(std::abs(e->direction.dot(rot.col(0))), 1.0, 1e-12);
    }
  // A rotated cube's face is flat only to rounding: the near faces rarely
  // prove it, the exact hull does.
  RecordProperty("by_near_faces", by_faces);
}
