// The witness point of a convex pair's depth (geometry/depth_witness.h), against
// points known by construction, and through the whole pair check (`at`).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "batch/pair_solve.h"
#include "box_points.h"
#include "geometry/depth_witness.h"
#include "geometry/hull.h"
#include "inline_part.h"
#include "solve/methods.h"

using namespace pd;
using pd_test::box_points;
using pd_test::inline_part;

namespace {

Points points(std::initializer_list<Vec3> l) {
  Points p(3, static_cast<Eigen::Index>(l.size()));
  int k = 0;
  for (const Vec3& v : l) p.col(k++) = v;
  return p;
}

Points placed(const Points& p, const Eigen::Matrix3d& r, const Vec3& t) {
  return (r * p).colwise() + t;
}

// Two overlapping axis-aligned boxes: the depth is the smallest overlap extent
// along an axis, and the deepest point is the centre of the overlap box.
struct BoxCase {
  Vec3 alo, ahi, blo, bhi;
  Vec3 direction() const {  // moving b along +d separates
    double best = INFINITY;
    Vec3 d = Vec3::UnitZ();
    for (int i = 0; i < 3; ++i) {
      const double up = ahi[i] - blo[i], down = bhi[i] - alo[i];
      if (up < best) best = up, d = Vec3::Unit(i);
      if (down < best) best = down, d = -Vec3::Unit(i);
    }
    return d;
  }
  Vec3 overlap_centre() const { return (alo.cwiseMax(blo) + ahi.cwiseMin(bhi)) / 2; }
};

}  // namespace

TEST(DepthWitness, OverlappingBoxesGiveTheOverlapCentreRotatedAndFarFromTheOrigin) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int nested_cases = 0;
  for (int n = 0; n < 200; ++n) {
    BoxCase c;
    c.alo = Vec3(u(rng), u(rng), u(rng));
    c.ahi = c.alo + Vec3(0.5 + u(rng), 0.5 + u(rng), 0.5 + u(rng));
    c.blo = c.alo + (c.ahi - c.alo).cwiseProduct(Vec3(u(rng), u(rng), u(rng))) * 0.9;  // in a
    c.bhi = c.blo + Vec3(0.3 + u(rng), 0.3 + u(rng), 0.3 + u(rng));
    const Vec3 d = c.direction();
    const Points a = box_points(c.alo, c.ahi), b = box_points(c.blo, c.bhi);
    const Vec3 got = depth_witness(a, b, d);
    // One box within the other along d: the slab between the support planes is
    // wider than the overlap, and the witness is clamped into the overlap box.
    int axis = 0;
    d.cwiseAbs().maxCoeff(&axis);
    const double slab_lo = d[axis] > 0 ? c.blo[axis] : c.alo[axis];
    const double slab_hi = d[axis] > 0 ? c.ahi[axis] : c.bhi[axis];
    const bool nested = slab_lo != std::max(c.alo[axis], c.blo[axis]) ||
                        slab_hi != std::min(c.ahi[axis], c.bhi[axis]);
    if (nested) {
      const Vec3 lo = c.alo.cwiseMax(c.blo), hi = c.ahi.cwiseMin(c.bhi);
      EXPECT_TRUE(((got - lo).array() >= -1e-12).all() && ((hi - got).array() >= -1e-12).all())
          << n;
      ++nested_cases;
      continue;
    }
    EXPECT_LT((got - c.overlap_centre()).norm(), 1e-12) << n;
    // The same pair turned and placed 1e4 away: the witness moves with it.
    const Eigen::Matrix3d r =
        Eigen::AngleAxisd(u(rng) * 6, Vec3(u(rng), u(rng), u(rng) + 0.1).normalized())
            .toRotationMatrix();
    const Vec3 t(1e4 * u(rng), -1e4, 5e3);
    const Vec3 w = depth_witness(placed(a, r, t), placed(b, r, t), r * d);
    EXPECT_LT((w - (r * c.overlap_centre() + t)).norm(), 1e-9) << n;
  }
  EXPECT_GT(nested_cases, 0);
  EXPECT_LT(nested_cases, 100);
}

TEST(DepthWitness, ApexOfASimplexInAFaceIsHalfwayBetweenApexAndFace) {
  // b's apex pokes 0.1 into a's top face: moving b up by 0.1 separates.
  const Points a = box_points(Vec3(-5, -5, -5), Vec3(5, 5, 0));
  const Points b = points({{0.3, 0.2, -0.1}, {-1, -1, 1}, {2, -1, 1}, {0.3, 2, 1}});
  const Vec3 w = depth_witness(a, b, Vec3::UnitZ());
  EXPECT_LT((w - Vec3(0.3, 0.2, -0.05)).norm(), 1e-12);
  // The same through the pair check: `at` is filled and in scene units.
  IpoptLocalSolver ipopt;
  for (Method m : {Method::kExact, Method::kMlsl}) {
    SolverSettings s;
    s.method = m;
    const PairResult r =
        solve_part_pair(0, inline_part("a", a), 1, inline_part("b", b), s, 0.01, ipopt);
    ASSERT_EQ(r.status, Status::kInterference);
    ASSERT_TRUE(r.at) << method_name(m);
    EXPECT_LT((*r.at - Vec3(0.3, 0.2, -0.05)).norm(), 1e-6) << method_name(m);
  }
}

TEST(DepthWitness, CrossedRidgesMeetAtTheCrossing) {
  // a: a ridge along x with its edge at z = 0; b: a ridge along y, edge down at z = −0.1.
  const Points a =
      points({{-5, 0, 0}, {5, 0, 0}, {-5, -1, -1}, {5, -1, -1}, {-5, 1, -1}, {5, 1, -1}});
  const Points b =
      points({{0, -5, -0.1}, {0, 5, -0.1}, {-1, -5, 0.9}, {-1, 5, 0.9}, {1, -5, 0.9}, {1, 5, 0.9}});
  EXPECT_LT((depth_witness(a, b, Vec3::UnitZ()) - Vec3(0, 0, -0.05)).norm(), 1e-12);
  // A slightly wrong direction still gives a point between the two edges.
  // (an edge–edge direction from Ipopt is known to about 1e-5).
  const Vec3 w = depth_witness(a, b, Vec3(1e-5, -1e-5, 1).normalized());
  EXPECT_LT((w - Vec3(0, 0, -0.05)).norm(), 1e-3);
}

TEST(DepthWitness, APlateInsideABlockIsMarkedOnThePlate) {
  // The middle of the slab (z = −0.995) lies outside the thin plate: clamped
  // into the region both boxes hold.
  const Points plate = box_points(Vec3(-1, -1, -0.01), Vec3(1, 1, 0.01));
  const Points block = box_points(Vec3(-2, -2, -2), Vec3(2, 2, 2));
  const Vec3 w = depth_witness(plate, block, Vec3::UnitZ());  // depth 2.01 upward
  EXPECT_NEAR(w.x(), 0.0, 1e-12);
  EXPECT_NEAR(w.y(), 0.0, 1e-12);
  EXPECT_GE(w.z(), -0.01);
  EXPECT_LE(w.z(), 0.01);
}

TEST(DepthWitness, ApartPairsGiveTheMiddleOfTheGap) {
  const Points a = box_points(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const Points b = box_points(Vec3(2, 0.5, 0.2), Vec3(3, 1.5, 0.7));
  EXPECT_LT((depth_witness(a, b, Vec3::UnitX()) - Vec3(1.5, 0.75, 0.45)).norm(), 1e-12);
  // Through a clearance check: the clearance violation is marked in the gap.
  IpoptLocalSolver ipopt;
  const PairResult r = solve_part_pair(0, inline_part("a", a), 1, inline_part("b", b),
                                       SolverSettings{}, 0.01, ipopt, {2.0, nullptr, std::nullopt});
  ASSERT_EQ(r.status, Status::kClearanceViolation);
  ASSERT_TRUE(r.at);
  EXPECT_LT((*r.at - Vec3(1.5, 0.75, 0.45)).norm(), 1e-6);
  // A clean pair has no place.
  const PairResult clean = solve_part_pair(0, inline_part("a", a), 1, inline_part("b", b),
                                           SolverSettings{}, 0.01, ipopt);
  EXPECT_EQ(clean.status, Status::kSeparated);
  EXPECT_FALSE(clean.at);
}

TEST(DepthWitness, DegenerateSetsGiveAFinitePoint) {
  const Points p = points({{0.5, 0.5, 0.5}});
  const Points box = box_points(Vec3(0, 0, 0), Vec3(1, 1, 1));
  EXPECT_LT((depth_witness(p, box, Vec3::UnitX()) - Vec3(0.5, 0.5, 0.5)).norm(), 1e-12);
  const Points seg = points({{0.5, 0.5, -1}, {0.5, 0.5, 2}});
  const Vec3 w = depth_witness(seg, box, Vec3::UnitX());
  EXPECT_TRUE(w.allFinite());
  EXPECT_NEAR(w.x(), 0.5, 1e-12);
  EXPECT_GE(w.z(), 0.0);
  EXPECT_LE(w.z(), 1.0);
}
