// The frame of a pair (frame.cpp): both parts mapped into the unit ball.
#include <gtest/gtest.h>

#include "box_points.h"
#include "geometry/frame.h"

using namespace pd;

namespace {
Points cube(double s, const Vec3& c = Vec3::Zero()) {
  return pd_test::box_points(c - Vec3::Constant(s), c + Vec3::Constant(s));
}
}  // namespace

TEST(Frame, PairFrameMapsIntoUnitBall) {
  const Points a = cube(10, Vec3(35000, 0, 0)), b = cube(1, Vec3(35010, 5, 0));
  const Frame f = pair_frame(a, b);
  EXPECT_LE(f.to_local(a).colwise().norm().maxCoeff(), 1.0 + 1e-12);
  EXPECT_LE(f.to_local(b).colwise().norm().maxCoeff(), 1.0 + 1e-12);
}
