// The convex hull of a point set (hull.cpp): degenerate sets keep their shape.
#include <gtest/gtest.h>

#include <stdexcept>

#include "box_points.h"
#include "geometry/hull.h"

using namespace pd;

namespace {
Points cube(double s, const Vec3& c = Vec3::Zero()) {
  return pd_test::box_points(c - Vec3::Constant(s), c + Vec3::Constant(s));
}
}  // namespace

TEST(Hull, CubeWithInteriorAndDuplicatePoints) {
  Points p(3, 8 + 8 + 5);
  p << cube(1), cube(1), Points::Random(3, 5) * 0.5;  // every corner twice (unwelded STL)
  const Hull h = convex_hull(p);
  EXPECT_EQ(h.dimension, 3);
  EXPECT_EQ(h.vertices.cols(), 8);
  EXPECT_TRUE(h.warnings.empty());
}

TEST(Hull, FlatSetKeepsItsPolygon) {
  Points p(3, 5);
  p << 0, 1, 1, 0, 0.5,  //
      0, 0, 1, 1, 0.5,   //
      7, 7, 7, 7, 7;
  const Hull h = convex_hull(p);
  EXPECT_EQ(h.dimension, 2);
  EXPECT_EQ(h.vertices.cols(), 4);
  ASSERT_FALSE(h.warnings.empty());
  EXPECT_NE(h.warnings[0].find("flat"), std::string::npos);
}

TEST(Hull, CollinearAndSinglePoint) {
  Points line(3, 4);
  line << 0, 1, 2, 3, 0, 2, 4, 6, 0, 0, 0, 0;
  const Hull h = convex_hull(line);
  EXPECT_EQ(h.dimension, 1);
  EXPECT_EQ(h.vertices.cols(), 2);
  Points one(3, 3);
  one.colwise() = Vec3(1, 2, 3);
  const Hull h0 = convex_hull(one);
  EXPECT_EQ(h0.dimension, 0);
  EXPECT_EQ(h0.vertices.cols(), 1);
}

TEST(Hull, ThinPlateStaysSolid) {
  for (double t : {1.0, 1e-3}) {  // 1000 x 1000 x 1 and a thickness ratio of 1e-6
    Points p = cube(1);
    p.row(0) *= 500;
    p.row(1) *= 500;
    p.row(2) *= t / 2;
    const Hull h = convex_hull(p);
    EXPECT_EQ(h.dimension, 3) << t;
    EXPECT_EQ(h.vertices.cols(), 8) << t;
  }
}

TEST(Hull, RejectsEmptyAndNonFinite) {
  EXPECT_THROW(convex_hull(Points(3, 0)), std::invalid_argument);
  Points p = cube(1);
  p(0, 3) = std::nan("");
  EXPECT_THROW(convex_hull(p), std::invalid_argument);
}

// The hull's dimension test works in the frame of the point set: its scale
// must not overflow (coordinates beyond ~1e154 squared) or underflow.
TEST(HugeCoordinates, HullDimensionIsScaleFree) {
  pd::Points tet(3, 5);
  tet << 0, 1, 0, 0, 0.2,  //
      0, 0, 1, 0, 0.2,     //
      0, 0, 0, 1, 0.2;
  for (const double s : {1e-300, 1e-160, 1.0, 1e160, 1e250, 1e307}) {
    const pd::Hull h = pd::convex_hull(tet * s);
    EXPECT_EQ(h.dimension, 3) << s;
    EXPECT_EQ(h.vertices.cols(), 4) << s;
    EXPECT_TRUE(h.warnings.empty()) << s;
  }
  // A set whose box half-diagonal exceeds the double range has no frame.
  pd::Points vast(3, 4);
  vast << -1.7e308, 1.7e308, 0, 0,  //
      0, 0, 1.7e308, 0,             //
      0, 0, 0, 1.7e308;
  EXPECT_THROW(pd::convex_hull(vast), std::invalid_argument);
}
