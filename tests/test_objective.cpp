// The depth objective's parametrisation (objective.cpp): directions and angles
// both ways, at the pole and across the wrap.
#include <gtest/gtest.h>

#include <cmath>

#include "solve/objective.h"

using namespace pd;

TEST(Objective, AnglesRoundTripWithPoleAndWrap) {
  double t = 0, p = 0;
  angles_from_direction(Vec3(0, 0, 1), t, p);
  EXPECT_EQ(t, M_PI / 2);  // the paper's fixed choice at the pole
  EXPECT_EQ(p, M_PI / 2);
  angles_from_direction(Vec3(1, -1e-300, 0), t, p);
  EXPECT_GE(t, 0.0);
  EXPECT_LT(t, 2 * M_PI);
  for (double th : {0.0, 1.0, 3.0, 6.2})
    for (double ph : {-1.5, 0.0, 0.7}) {
      angles_from_direction(direction_from_angles(th, ph), t, p);
      EXPECT_NEAR(t, th, 1e-12);
      EXPECT_NEAR(p, ph, 1e-12);
    }
}
