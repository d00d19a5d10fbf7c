// The motion sweep of a pair (batch/motion_sweep.h): the signed distance over
// a time grid against analytic values and against the exact hull at each step,
// warm-started or not; the box a moving part sweeps. (Warm start: the suite
// keeps its name, Checks, which scripts/sanitize.sh lists among the slow tests.)
#include <gtest/gtest.h>

#include <cmath>

#include "batch/motion_sweep.h"
#include "box_points.h"
#include "corpus/generators.h"
#include "geometry/hull.h"
#include "solve/signed_distance.h"

using namespace pd;

namespace {

// A part of one unit cube at (x, 0, 0), moving at `velocity` when given.
Part cube_part(double x, std::optional<Vec3> velocity = std::nullopt) {
  Part p;
  p.id = "cube";
  const Points v = pd_test::box_points(Vec3(x, 0, 0), Vec3(x + 1, 1, 1));
  p.pieces.push_back(convex_hull(v));
  p.box = Aabb::of(v);
  if (velocity) p.motion = RigidMotion{Vec3::Zero(), Vec3::Zero(), *velocity};
  return p;
}

}  // namespace

TEST(MotionSweep, ASlidingCubeFollowsTheAnalyticSeries) {
  // b slides along −x through a at 1 unit/s: s(t) = t − 2 until contact at t = 2,
  // then the overlap 1 − |t − 3| (the x overlap is the smallest way out).
  const Part a = cube_part(0), b = cube_part(3, Vec3(-1, 0, 0));
  MotionCheck m;
  m.grid = {0, 4, 0.5};
  m.series = true;
  IpoptLocalSolver ipopt;
  const MotionSweep s = sweep_pair(a, b, m, SolverSettings{}, ipopt);
  EXPECT_TRUE(s.fallback.empty()) << s.fallback;
  EXPECT_EQ(s.trace.steps, 9);
  EXPECT_NEAR(s.trace.max_depth, 1.0, 1e-9);
  EXPECT_EQ(s.trace.t_max_depth, 3.0);
  ASSERT_TRUE(s.trace.min_distance);
  EXPECT_NEAR(*s.trace.min_distance, 0.0, 1e-9);
  EXPECT_NEAR(std::abs(s.direction_at_max.x()), 1.0, 1e-9);
  ASSERT_EQ(s.trace.series.size(), 9u);
  for (const auto& [t, v] : s.trace.series)
    EXPECT_NEAR(v, t < 2 ? t - 2 : 1 - std::abs(t - 3), 1e-9) << "t = " << t;
  // Without the series only the extremes are kept, the same ones.
  m.series = false;
  const MotionSweep lean = sweep_pair(a, b, m, SolverSettings{}, ipopt);
  EXPECT_TRUE(lean.trace.series.empty());
  EXPECT_EQ(lean.trace.t_max_depth, 3.0);
}

TEST(MotionSweep, TheSweptBoxCoversEveryStep) {
  const TimeGrid grid{0, 4, 0.5};
  const Part still = cube_part(0);
  const Aabb s = swept_box(still, grid);
  EXPECT_EQ(s.lo, Vec3(0, 0, 0));
  EXPECT_EQ(s.hi, Vec3(1, 1, 1));
  const Aabb moving = swept_box(cube_part(3, Vec3(-1, 0.5, 0)), grid);
  EXPECT_NEAR(moving.lo.x(), -1.0, 1e-12);  // at t = 4
  EXPECT_NEAR(moving.hi.x(), 4.0, 1e-12);   // at t = 0
  EXPECT_NEAR(moving.lo.y(), 0.0, 1e-12);
  EXPECT_NEAR(moving.hi.y(), 3.0, 1e-12);  // 1 + 0.5·4
  EXPECT_NEAR(moving.hi.z(), 1.0, 1e-12);
}

TEST(Checks, WarmStartGivesTheColdValues) {
  SphereSampler rng(2006);
  const testgen::PairCase c = testgen::zhou_spheres(rng, 60);
  Part a, b;
  a.pieces.push_back(convex_hull(c.a));
  b.pieces.push_back(convex_hull(c.b));
  a.motion = RigidMotion{Vec3(0, 0, 0.05), Vec3::Zero(), Vec3::Zero()};
  b.motion = RigidMotion{Vec3::Zero(), Vec3::Zero(), -0.01 * Vec3(2, 1, 3)};
  MotionCheck m;
  m.grid = {0, 1200, 20};  // apart until t ≈ 480 s, then overlapping
  m.series = true;
  IpoptLocalSolver ipopt;
  const MotionSweep warm = sweep_pair(a, b, m, SolverSettings{}, ipopt, true);
  const MotionSweep cold = sweep_pair(a, b, m, SolverSettings{}, ipopt, false);
  ASSERT_EQ(warm.trace.series.size(), cold.trace.series.size());
  int apart = 0, overlapping = 0;
  for (size_t k = 0; k < warm.trace.series.size(); ++k) {
    (warm.trace.series[k].second < 0 ? apart : overlapping)++;
    const double t = warm.trace.series[k].first;
    // Both against the exact hull at that time.
    const Points pa = a.motion->at(a.pieces[0].vertices, t),
                 pb = b.motion->at(b.pieces[0].vertices, t);
    SolverSettings e;
    e.method = Method::kExact;
    const double exact = signed_distance(pa, pb, e, ipopt, std::nullopt).value;
    EXPECT_NEAR(warm.trace.series[k].second, exact, 1e-8) << t;
    EXPECT_NEAR(cold.trace.series[k].second, exact, 1e-8) << t;
  }
  EXPECT_GT(apart, 10);  // both branches of the warm start were exercised
  EXPECT_GT(overlapping, 10);
}
