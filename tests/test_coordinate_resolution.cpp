// The resolution of a part's coordinates (coordinate_resolution.cpp): the unit
// in the last place at their magnitude, carried by the placement.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>

#include "geometry/coordinate_resolution.h"

using namespace pd;

TEST(CoordinateResolution, TheSpacingOfFloatsAtAMagnitude) {
  // float32 holds 24 significant bits: at 35,000 (2^15 <= x < 2^16) a step is 2^-8.
  EXPECT_EQ(coordinate_step(35000, true), std::ldexp(1.0, -8));
  EXPECT_EQ(coordinate_step(-35000, true), std::ldexp(1.0, -8));
  EXPECT_EQ(coordinate_step(1.0, true), std::ldexp(1.0, -23));
  EXPECT_EQ(coordinate_step(1.0, false), DBL_EPSILON);
  EXPECT_EQ(coordinate_step(std::nextafter(2.0, 0.0), false), DBL_EPSILON);
  EXPECT_EQ(coordinate_step(2.0, false), 2 * DBL_EPSILON);
  // The step is the distance to the next representable number.
  for (const double x : {0.3, 7.0, 35000.0, 1e10})
    EXPECT_EQ(coordinate_step(x, false), std::nextafter(x, INFINITY) - x) << x;
  EXPECT_EQ(coordinate_step(35000.0, true), double(std::nextafter(35000.0f, INFINITY)) - 35000.0);
  // Zero and subnormals: the smallest normal's spacing.
  EXPECT_EQ(coordinate_step(0.0, true), coordinate_step(FLT_MIN, true));
  EXPECT_GT(coordinate_step(0.0, false), 0.0);
}

TEST(CoordinateResolution, CarriedByThePlacementAndNoFinerThanDoubles) {
  // A float32 file at 35 m, read in mm (stretch 1000).
  const double r = coordinate_resolution(35.0, true, 1000.0, 35000.0);
  EXPECT_EQ(r, coordinate_step(35.0, true) * 1000.0);
  // Inline doubles near the origin placed far away: the placement's double spacing.
  EXPECT_EQ(coordinate_resolution(1.0, false, 1.0, 1e12), coordinate_step(1e12, false));
  Points p(3, 2);
  p << 1, -7,  //
      2, 3,    //
      -0.5, 4;
  EXPECT_EQ(max_abs_coordinate(p), 7.0);
  EXPECT_EQ(max_abs_coordinate(Points(3, 0)), 0.0);
}
