// Rigid motion and the time grid (motion.h).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "geometry/motion.h"

using namespace pd;

TEST(Motion, RotationAboutAnAxisThroughAPointPlusVelocity) {
  RigidMotion m;
  m.angular = Vec3(0, 0, M_PI / 2);  // a quarter turn per second about z
  m.about = Vec3(1, 0, 0);
  m.velocity = Vec3(0, 0, 2);
  Points x(3, 2);
  x << 2, 1,  //
      0, 0,   //
      0, 5;
  const Points at1 = m.at(x, 1.0);
  // (2, 0, 0) turns about (1, 0, z) to (1, 1, 0), then rises by 2.
  EXPECT_NEAR((at1.col(0) - Vec3(1, 1, 2)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((at1.col(1) - Vec3(1, 0, 7)).norm(), 0.0, 1e-12);  // on the axis: only rises
  EXPECT_EQ(m.at(x, 0.0), x);
  RigidMotion still;
  EXPECT_EQ(still.at(x, 3.0), x);
}

TEST(Motion, TimeGridStepsIncludeTheEnd) {
  const TimeGrid g{0.0, 1.0, 0.1};
  EXPECT_EQ(g.steps(), 11);  // 0, 0.1, …, 1.0: the end within rounding of a step
  EXPECT_DOUBLE_EQ(g.time(10), 1.0);
  EXPECT_EQ((TimeGrid{2.0, 2.0, 1.0}.steps()), 1);
  EXPECT_EQ((TimeGrid{0.0, 0.95, 0.1}.steps()), 10);
  EXPECT_THROW((TimeGrid{0.0, 1e7, 1e-3}.steps()), std::domain_error);  // 1e10 steps
  EXPECT_THROW((TimeGrid{1.0, 0.0, 0.1}.steps()), std::domain_error);   // backwards
  // At most kMaxTimeSteps, and the limit itself is allowed.
  EXPECT_EQ((TimeGrid{0.0, 999999.0, 1.0}.steps()), kMaxTimeSteps);
  EXPECT_THROW((TimeGrid{0.0, 1000000.0, 1.0}.steps()), std::domain_error);
}

TEST(TimeGridLimits, StepsNeverCastOutOfRange) {
  EXPECT_EQ((pd::TimeGrid{0, 4, 1}).steps(), 5);
  EXPECT_EQ((pd::TimeGrid{0, 4, 0.5}).steps(), 9);
  EXPECT_THROW((pd::TimeGrid{0, 4, 1e-300}).steps(), std::domain_error);
  EXPECT_THROW((pd::TimeGrid{-1e308, 1e308, 1}).steps(), std::domain_error);
  EXPECT_THROW((pd::TimeGrid{0, 9.3e18, 1}).steps(), std::domain_error);
}
