// The facet snap (solve/facet_snap.h) on unit cubes overlapping by 0.1 along x:
// a direction next to a facet normal of P − Q lands on it exactly (the depth
// 0.1 to one rounding), oriented with the direction; a vertex or an edge is no
// facet; a descent's end point, too far off for the tight bands, still snaps.
#include <gtest/gtest.h>

#include "box_points.h"
#include "solve/facet_snap.h"
#include "solve/objective.h"

using namespace pd;
using pd_test::box_points;

namespace {

PairProblem cubes() {
  return PairProblem(box_points(Vec3::Zero(), Vec3::Ones()),
                     box_points(Vec3(0.9, 0, 0), Vec3(1.9, 1, 1)));
}

void expect_axis(const std::optional<Vec3>& n, const Vec3& axis) {
  ASSERT_TRUE(n.has_value());
  EXPECT_NEAR((*n - axis).norm(), 0.0, 1e-15) << n->transpose();
}

}  // namespace

TEST(FacetSnap, ADirectionBesideAFacetLandsOnItExactly) {
  const PairProblem pr = cubes();
  const double scale = pr.frame().scale;
  const auto n = snap_to_facet(pr.p(), pr.q(), Vec3(1, 1e-9, -2e-9).normalized());
  expect_axis(n, Vec3::UnitX());
  EXPECT_NEAR(pr.gap(*n) * scale, 0.1, 1e-15);
  // The facet on the far side (−x, gap 1.9), oriented with the direction given.
  const auto far = snap_to_facet(pr.p(), pr.q(), Vec3(-1, 2e-9, 1e-9).normalized());
  expect_axis(far, -Vec3::UnitX());
  EXPECT_NEAR(pr.gap(*far) * scale, 1.9, 1e-15);
  // A y facet: a face of P minus a face of Q, both of side 1.
  expect_axis(snap_to_facet(pr.p(), pr.q(), Vec3(-3e-9, 1, 1e-9).normalized()), Vec3::UnitY());
}

TEST(FacetSnap, AVertexOrAnEdgeIsNoFacet) {
  const PairProblem pr = cubes();
  // One vertex of each cube active: a vertex of P − Q.
  EXPECT_FALSE(snap_to_facet(pr.p(), pr.q(), Vec3(1, 1.1, 1.2).normalized()));
  // Two of each, along z: an edge of P − Q (rank 1).
  EXPECT_FALSE(snap_to_facet(pr.p(), pr.q(), Vec3(1, 1, 0).normalized()));
  EXPECT_FALSE(snap_from_descent(pr.p(), pr.q(), Vec3(1, 1.1, 1.2).normalized()));
}

TEST(FacetSnap, ADescentsEndPointSnapsFromItsLooserBands) {
  // 2e-4 rad off +x: one vertex of each cube within the tight bands, a face
  // within kDescentSnapBand.
  const PairProblem pr = cubes();
  const Vec3 v = Vec3(1, 1e-4, 2e-4).normalized();
  EXPECT_FALSE(snap_to_facet(pr.p(), pr.q(), v));
  const auto n = snap_from_descent(pr.p(), pr.q(), v);
  expect_axis(n, Vec3::UnitX());
  EXPECT_NEAR(pr.gap(*n) * pr.frame().scale, 0.1, 1e-15);
}
