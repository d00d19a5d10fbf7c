// Where a BCF viewpoint looks (bcf_view.cpp): the camera on a finding.
#include <gtest/gtest.h>

#include <cmath>

#include "report/bcf_view.h"
#include "tolerances.h"

TEST(BcfView, CameraLooksAcrossTheDepthAtTheFinding) {
  const pd::Aabb a{pd::Vec3(0, 0, 0), pd::Vec3(10, 10, 10)};
  const pd::Aabb b{pd::Vec3(8, 2, 2), pd::Vec3(12, 6, 6)};  // the smaller part
  const double fov = pd::tol::kBcfFieldOfView * M_PI / 180.0;
  for (const pd::Vec3& n :
       std::vector<pd::Vec3>{pd::Vec3::UnitZ(), pd::Vec3::UnitX(), pd::Vec3(1, 1, -1).normalized(),
                             pd::Vec3(0.3, -0.2, 0.9).normalized()}) {
    const pd::ViewTarget t = pd::view_target(pd::Vec3(9, 4, 4), a, b);
    EXPECT_TRUE(t.at);
    EXPECT_EQ(t.centre, pd::Vec3(9, 4, 4));
    EXPECT_NEAR(t.radius, 0.5 * std::sqrt(48.0), 1e-12);  // half the smaller box's diagonal
    const pd::PerspectiveCamera c = pd::camera_on(t, n);
    EXPECT_NEAR(c.direction.norm(), 1.0, 1e-12);
    EXPECT_NEAR(c.up.norm(), 1.0, 1e-12);
    EXPECT_NEAR(c.direction.dot(c.up), 0.0, 1e-12);
    // The camera looks at the centre, and the ball just fills the vertical view.
    const pd::Vec3 to = t.centre - c.viewpoint;
    EXPECT_NEAR(to.normalized().dot(c.direction), 1.0, 1e-12);
    EXPECT_NEAR(t.radius / to.norm(), std::sin(fov / 2), 1e-12);
    // Across the depth: the depth shows as a length, not a point.
    EXPECT_LT(std::abs(c.direction.dot(n)), 0.9) << n.transpose();
    EXPECT_GT(c.field_of_view, 0.0);
    EXPECT_LT(c.field_of_view, 180.0);
  }
  // Depth along z (a lid on a frame): a level view, z up.
  const pd::PerspectiveCamera level =
      pd::camera_on(pd::view_target(pd::Vec3(1, 1, 1), a, b), pd::Vec3::UnitZ());
  EXPECT_NEAR(level.direction.z(), 0.0, 1e-12);
  EXPECT_NEAR(level.up.z(), 1.0, 1e-12);
  // Without `at`: the centre of the boxes' overlap; boxes apart: between them.
  const pd::ViewTarget o = pd::view_target(std::nullopt, a, b);
  EXPECT_FALSE(o.at);
  EXPECT_EQ(o.centre, pd::Vec3(9, 4, 4));
  const pd::Aabb far{pd::Vec3(30, 0, 0), pd::Vec3(31, 1, 1)};
  const pd::ViewTarget m = pd::view_target(std::nullopt, a, far);
  EXPECT_EQ(m.centre, pd::Vec3(0.5 * (5 + 30.5), 5 * 0.5 + 0.25, 5 * 0.5 + 0.25));
  EXPECT_GE(m.radius, 0.5 * (pd::Vec3(5, 5, 5) - pd::Vec3(30.5, 0.5, 0.5)).norm());
}
