// SoaPoints::max_dot / min_dot (the sampling's and the certificate's support
// values without a temporary) against Eigen's v^T·P with its argmax.
#include <gtest/gtest.h>

#include "corpus/generators.h"
#include "solve/support_scan.h"

using namespace pd;

TEST(SupportScan, MatchesEigensSupportAndFirstIndexAtEveryBlockBoundary) {
  SphereSampler r(7);
  // Sizes around the 64-value blocks, and points repeated so that the maximum
  // is reached several times (the first index must win, as in Eigen).
  for (int n : {1, 2, 63, 64, 65, 127, 128, 129, 300}) {
    Points x(3, n);
    for (int k = 0; k < n; ++k) x.col(k) = r.direction() * (1 + r.uniform());
    if (n > 70) x.col(n - 1) = x.col(66) = x.col(5) = 3 * r.direction();  // the top, 3 times
    const SoaPoints s(x);
    for (int t = 0; t < 50; ++t) {
      const Vec3 v = t == 0 && n > 5 ? Vec3(x.col(5).normalized()) : r.direction();
      Eigen::Index ie = 0, is = 0, je = 0, js = 0;
      const double hi = (v.transpose() * x).maxCoeff(&ie);
      const double lo = (v.transpose() * x).minCoeff(&je);
      SCOPED_TRACE("n " + std::to_string(n) + " t " + std::to_string(t));
      EXPECT_NEAR(s.max_dot(v, &is), hi, 1e-15);
      EXPECT_NEAR(s.min_dot(v, &js), lo, 1e-15);
      EXPECT_EQ(is, ie);
      EXPECT_EQ(js, je);
      EXPECT_DOUBLE_EQ(s.max_dot(v), x.col(is).dot(v));
    }
  }
}
