// Axis-aligned boxes (aabb.cpp): of points, closed overlap, inflate, merge.
#include <gtest/gtest.h>

#include "geometry/aabb.h"

using namespace pd;

TEST(Aabb, OfPointsOverlapInflateMerge) {
  Points p(3, 3);
  p << 1, -2, 0.5,  //
      4, 3, -1,     //
      0, 7, 2;
  const Aabb b = Aabb::of(p);
  EXPECT_EQ(b.lo, Vec3(-2, -1, 0));
  EXPECT_EQ(b.hi, Vec3(1, 4, 7));
  // Closed: sharing a face or a corner overlaps; a gap does not.
  const Aabb face{Vec3(1, 0, 0), Vec3(2, 1, 1)}, corner{b.hi, b.hi + Vec3::Ones()},
      apart{Vec3(1.0000001, 0, 0), Vec3(2, 1, 1)};
  EXPECT_TRUE(b.overlaps(face));
  EXPECT_TRUE(face.overlaps(b));
  EXPECT_TRUE(b.overlaps(corner));
  EXPECT_FALSE(b.overlaps(apart));
  EXPECT_TRUE(b.inflated(1e-6).overlaps(apart));
  EXPECT_EQ(b.inflated(0.5).lo, Vec3(-2.5, -1.5, -0.5));
  const Aabb m = b.merged(apart);
  EXPECT_EQ(m.lo, Vec3(-2, -1, 0));
  EXPECT_EQ(m.hi, Vec3(2, 4, 7));
}
