// The smooth descent (solve/smooth_descent.h) on unit cubes overlapping along
// the diagonal: Q = P + (0.1, 0.2, 0.3), so P − Q is the box [−1.1, 0.9] ×
// [−1.2, 0.8] × [−1.3, 0.7], whose gap has a local minimum at each facet
// normal (0.9 at +x, 1.1 at −x, 0.8 at +y, 1.2 at −y, 0.7 at +z, 1.3 at −z),
// each with a basin reaching at least 28° around it. A start 10° off an axis
// ends at that axis, and the smoothed value bounds the gap there from above
// within μ·log(n·m).
#include <gtest/gtest.h>

#include <cmath>

#include "box_points.h"
#include "solve/objective.h"
#include "solve/smooth_descent.h"
#include "tolerances.h"

using namespace pd;
using pd_test::box_points;

namespace {

// f_μ(v) as the header defines it, every term counted.
double smoothed_gap(const PairProblem& pr, const Vec3& v, double mu) {
  const auto log_sum_exp = [&](const Eigen::RowVectorXd& s) {
    const double top = s.maxCoeff();
    return top +
           mu * std::log(
                    (s.array() - top).unaryExpr([&](double x) { return std::exp(x / mu); }).sum());
  };
  return log_sum_exp(v.transpose() * pr.p()) + log_sum_exp(-(v.transpose() * pr.q()));
}

}  // namespace

TEST(SmoothDescent, EachStartEndsAtTheAxisOfItsBasin) {
  const PairProblem pr(box_points(Vec3::Zero(), Vec3::Ones()),
                       box_points(Vec3(0.1, 0.2, 0.3), Vec3(1.1, 1.2, 1.3)));
  const double final_mu = std::end(tol::kDescentMu)[-1];
  const double values[] = {0.9, 1.1, 0.8, 1.2, 0.7, 1.3};  // +x, −x, +y, −y, +z, −z
  for (int k = 0; k < 6; ++k) {
    const Vec3 axis = (k % 2 ? -1.0 : 1.0) * Vec3::Unit(k / 2);
    const Vec3 start =
        axis + 0.15 * Vec3::Unit((k / 2 + 1) % 3) - 0.1 * Vec3::Unit((k / 2 + 2) % 3);
    SCOPED_TRACE(start.transpose());
    const DescentOutcome d = smooth_descent(pr.p(), pr.q(), start);
    EXPECT_NEAR(d.v.norm(), 1.0, 1e-15);
    EXPECT_LT(angle_between(d.v, axis), 1e-3) << d.v.transpose();
    EXPECT_NEAR(pr.gap(d.v) * pr.frame().scale, values[k], 1e-3);
    EXPECT_GT(d.evaluations, 0);
    EXPECT_EQ(d.mu, final_mu);
    // f_μ >= gap, within μ·log(8·8) (both sums over 8 vertices).
    EXPECT_NEAR(d.smoothed, smoothed_gap(pr, d.v, final_mu), 1e-15);
    const double gap = pr.gap(d.v);
    EXPECT_GE(d.smoothed, gap);
    EXPECT_LE(d.smoothed, gap + final_mu * std::log(64.0) + 1e-15);
  }
}

TEST(SmoothDescent, AStartAtAMinimumStays) {
  const PairProblem pr(box_points(Vec3::Zero(), Vec3::Ones()),
                       box_points(Vec3(0.1, 0.2, 0.3), Vec3(1.1, 1.2, 1.3)));
  // The smoothed minimum lies within about μ of the kink at +z, not on it.
  const DescentOutcome d = smooth_descent(pr.p(), pr.q(), Vec3(0, 0, 2));  // normalised
  EXPECT_LT(angle_between(d.v, Vec3::UnitZ()), 1e-3) << d.v.transpose();
  EXPECT_NEAR(pr.gap(d.v) * pr.frame().scale, 0.7, 1e-3);
}
