// The intersection of two convex hulls (convex_overlap.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "box_points.h"
#include "geometry/convex_overlap.h"
#include "geometry/hull.h"

using namespace pd;
using pd_test::box_points;

TEST(ConvexOverlap, TwoBoxesOverlapInTheirIntersection) {
  const auto o =
      convex_overlap(box_points({0, 0, 0}, {2, 2, 2}), box_points({1, -1, 0.5}, {3, 1, 4}));
  ASSERT_TRUE(o);
  EXPECT_EQ(o->dimension, 3);
  ASSERT_EQ(o->vertices.cols(), 8);
  const Vec3 lo = o->vertices.rowwise().minCoeff(), hi = o->vertices.rowwise().maxCoeff();
  EXPECT_NEAR((lo - Vec3(1, 0, 0.5)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((hi - Vec3(2, 1, 2)).norm(), 0.0, 1e-12);
  // A box inside another: itself.
  const auto inner =
      convex_overlap(box_points({0, 0, 0}, {4, 4, 4}), box_points({1, 1, 1}, {2, 3, 2}));
  ASSERT_TRUE(inner);
  EXPECT_NEAR((inner->vertices.rowwise().maxCoeff() - Vec3(2, 3, 2)).norm(), 0.0, 1e-12);
}

TEST(ConvexOverlap, TouchingApartOrFlatIsNoSolidOverlap) {
  const Points a = box_points({0, 0, 0}, {1, 1, 1});
  EXPECT_FALSE(convex_overlap(a, box_points({1, 0, 0}, {2, 1, 1})));      // sharing a face
  EXPECT_FALSE(convex_overlap(a, box_points({3, 0, 0}, {4, 1, 1})));      // apart
  EXPECT_FALSE(convex_overlap(a, box_points({0.5, 0, 0}, {0.5, 1, 1})));  // a flat set
  EXPECT_FALSE(convex_overlap(a, Points(3, 3)));                          // too few points
}
