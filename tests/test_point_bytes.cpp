// Point sets as bytes (point_bytes.cpp): lossless both ways, and a short, long
// or garbled entry read as nothing.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/point_bytes.h"

using namespace pd;

TEST(PointBytes, RoundTripBitForBitAndRefuseWrongLengths) {
  Points a(3, 4), b(3, 0), c(3, 1);
  a.setRandom();
  a(0, 0) = 1.0 / 3.0;
  a(1, 1) = -0.0;
  a(2, 2) = std::nextafter(1e300, 0.0);
  c << 1, 2, 3;
  const std::string bytes = point_sets_bytes({a, b, c});
  const std::string prefix = "header";
  const auto back = point_sets_from_bytes(prefix + bytes, prefix.size(), 3);
  ASSERT_TRUE(back);
  ASSERT_EQ(back->size(), 3u);
  EXPECT_EQ((*back)[0], a);
  EXPECT_TRUE(std::signbit((*back)[0](1, 1)));  // -0 stays -0
  EXPECT_EQ((*back)[1].cols(), 0);
  EXPECT_EQ((*back)[2], c);
  EXPECT_FALSE(point_sets_from_bytes(bytes, 0, 2));                              // bytes left over
  EXPECT_FALSE(point_sets_from_bytes(bytes, 0, 4));                              // a set missing
  EXPECT_FALSE(point_sets_from_bytes(bytes.substr(0, bytes.size() - 1), 0, 3));  // cut short
  EXPECT_FALSE(point_sets_from_bytes(bytes + "x", 0, 3));
  EXPECT_TRUE(point_sets_from_bytes("", 0, 0));
}
