// The certificate's grid and cover (solve/certificate.h): the cube-sphere cells
// tile the sphere, a cell's support point is one of P − Q's, and the caps left
// open hold every direction whose gap may lie below the best known, so that
// outside them the gap is above it. On unit cubes overlapping by 0.1 along x
// (depth 0.1 at +x, exactly) and on a pair whose depth the exact method gives.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "box_points.h"
#include "method_solve.h"
#include "solve/certificate.h"
#include "solve/mlsl.h"
#include "tolerances.h"

using namespace pd;
using pd_test::box_points;

namespace {

bool covered(const CapCover& c, const Vec3& u) {
  for (const auto& [centre, radius] : c.caps)
    if (angle_between(centre, u) <= radius) return true;
  return false;
}

CapCover cover_at(const PairProblem& pr, double best) {
  return open_region_caps(pr, best, tol::kCertificateGrid, tol::kCertificateCapAngle,
                          tol::kCertificateCaps);
}

// What the cover promises: the gap is above `best` at every direction outside
// its caps (tried at random directions), and `optimum` is inside one.
void expect_certifies(const PairProblem& pr, const CapCover& c, double best, const Vec3& optimum) {
  ASSERT_TRUE(c.ok);
  EXPECT_FALSE(c.caps.empty());
  EXPECT_LE(c.caps.size(), size_t(tol::kCertificateCaps));
  for (const auto& [centre, radius] : c.caps) {
    EXPECT_NEAR(centre.norm(), 1.0, 1e-12);
    EXPECT_LE(radius, tol::kCertificateCapAngle);
  }
  EXPECT_TRUE(covered(c, optimum));
  SphereSampler r(3);
  int outside = 0;
  for (int k = 0; k < 4000; ++k) {
    const Vec3 u = r.direction();
    if (covered(c, u)) continue;
    ++outside;
    EXPECT_GT(pr.gap(u), best) << u.transpose();
  }
  EXPECT_GT(outside, 3000);  // the caps are a small part of the sphere
}

}  // namespace

TEST(Certificate, CubeSphereCellsTileTheSphere) {
  const int n = 4;
  const std::vector<SphereCell>& cells = cube_sphere_cells(n);
  ASSERT_EQ(cells.size(), size_t(6 * n * n));
  EXPECT_EQ(&cube_sphere_cells(n), &cells);  // made once
  std::set<std::tuple<int, int, int>> seen;
  for (const SphereCell& c : cells) {
    seen.insert({c.face, c.i, c.j});
    EXPECT_NEAR(c.centre.norm(), 1.0, 1e-15);
    EXPECT_GT(c.radius, 0.0);
    EXPECT_LT(c.radius, M_PI / n);  // a face spans a quarter turn
    for (const Vec3& k : c.corners) EXPECT_LE(angle_between(c.centre, k), c.radius);
  }
  EXPECT_EQ(seen.size(), cells.size());
  // Every direction lies in a cell; the face's own axis is a corner of four.
  SphereSampler r(11);
  for (int k = 0; k < 1000; ++k) {
    const Vec3 u = r.direction();
    bool in = false;
    for (const SphereCell& c : cells) in = in || angle_between(c.centre, u) <= c.radius;
    EXPECT_TRUE(in) << u.transpose();
  }
  int at_x = 0;
  for (const SphereCell& c : cells)
    for (const Vec3& k : c.corners) at_x += (k - Vec3::UnitX()).norm() < 1e-15;
  EXPECT_EQ(at_x, 4);
}

TEST(Certificate, CellSupportsAreSupportPointsOfTheDifference) {
  const Points a = box_points(Vec3::Zero(), Vec3::Ones());
  const Points b = box_points(Vec3(0.9, 0.2, -0.3), Vec3(1.9, 0.7, 0.4));
  const PairProblem pr(a, b);
  const int grid = 6;
  const CellSupports s = cell_supports(pr, grid);
  const auto& cells = cube_sphere_cells(grid);
  ASSERT_EQ(s.x.size(), cells.size());
  ASSERT_EQ(s.g.size(), cells.size());
  for (size_t k = 0; k < cells.size(); ++k) {
    const Vec3& c = cells[k].centre;
    // The largest (p_i − q_j)·c over every vertex pair, and one pair reaching it.
    double top = -INFINITY;
    bool is_a_pair = false;
    for (Eigen::Index i = 0; i < pr.p().cols(); ++i)
      for (Eigen::Index j = 0; j < pr.q().cols(); ++j) {
        const Vec3 d = pr.p().col(i) - pr.q().col(j);
        top = std::max(top, d.dot(c));
        is_a_pair = is_a_pair || d == s.x[k];
      }
    EXPECT_NEAR(s.g[k], top, 1e-15) << k;
    EXPECT_NEAR(s.x[k].dot(c), s.g[k], 1e-15) << k;
    EXPECT_TRUE(is_a_pair) << k;
    EXPECT_NEAR(s.g[k], pr.gap(c), 1e-15) << k;
  }
}

TEST(Certificate, TheCubesDepthDirectionIsTheOnlyOpenRegion) {
  const Points a = box_points(Vec3::Zero(), Vec3::Ones());
  const Points b = box_points(Vec3(0.9, 0, 0), Vec3(1.9, 1, 1));
  const PairProblem pr(a, b);
  const double best = pr.gap(Vec3::UnitX());
  EXPECT_NEAR(best * pr.frame().scale, 0.1, 1e-15);
  const CapCover c = cover_at(pr, best);
  expect_certifies(pr, c, best, Vec3::UnitX());
  ASSERT_EQ(c.caps.size(), 1u);  // one group of open cells, about +x
  EXPECT_EQ(c.evaluations, long(6 * tol::kCertificateGrid * tol::kCertificateGrid));
  // From supports computed once: the same cover, no evaluations of its own.
  const CapCover again =
      open_region_caps(cell_supports(pr, tol::kCertificateGrid), best, tol::kCertificateGrid,
                       tol::kCertificateCapAngle, tol::kCertificateCaps);
  EXPECT_EQ(again.evaluations, 0);
  ASSERT_EQ(again.caps.size(), c.caps.size());
  EXPECT_EQ(again.caps[0].first, c.caps[0].first);
  EXPECT_EQ(again.caps[0].second, c.caps[0].second);
}

TEST(Certificate, TheExactDepthDirectionIsCovered) {
  SphereSampler r(8);
  for (int k = 0; k < 3; ++k) {
    const testgen::PairCase pc = testgen::vertex_class(r, 12);
    const PairProblem pr(pc.a, pc.b);
    const DepthSolution e = pd_test::solve(pc, Method::kExact);
    ASSERT_GT(e.depth, 0);
    const double best = pr.gap(e.direction);
    EXPECT_NEAR(best * pr.frame().scale, e.depth, 1e-9 * e.depth);
    expect_certifies(pr, cover_at(pr, best), best, e.direction);
  }
}

TEST(Certificate, ABestAboveEveryGapCannotBeCovered) {
  // Every cell is open: far more of the sphere than kCertificateCaps caps hold.
  const PairProblem pr(box_points(Vec3::Zero(), Vec3::Ones()),
                       box_points(Vec3(0.9, 0, 0), Vec3(1.9, 1, 1)));
  EXPECT_FALSE(cover_at(pr, 10.0).ok);
}
