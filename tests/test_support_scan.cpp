// SoaPoints::max_dot / min_dot (the sampling's and the certificate's support
// values without a temporary) against Eigen's v^T·P with its argmax.
#include <gtest/gtest.h>

#include <vector>

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

TEST(SupportScan, BatchedDirectionsGiveEachSupportBitForBitWithItsFirstIndex) {
  SphereSampler r(11);
  // Direction counts around the 32-direction blocks; sizes from empty to several
  // 64-point blocks; repeated points so that ties must keep the first index.
  for (int n : {0, 1, 3, 8, 64, 65, 200}) {
    Points x(3, n);
    for (int k = 0; k < n; ++k) x.col(k) = r.direction() * (1 + r.uniform());
    if (n > 10) x.col(n - 1) = x.col(7) = x.col(3) = 3 * r.direction();  // the top, 3 times
    const SoaPoints s(x);
    for (size_t count : {size_t(1), size_t(31), size_t(32), size_t(33), size_t(100)}) {
      std::vector<Vec3> v(count);
      for (Vec3& d : v) d = r.direction();
      if (n > 10) v[0] = x.col(3).normalized();  // the tied top
      for (double sign : {1.0, -1.0}) {
        std::vector<double> out(count);
        std::vector<Eigen::Index> at(count);
        s.max_dots(v.data(), count, sign, out.data(), at.data());
        std::vector<double> plain(count);
        s.max_dots(v.data(), count, sign, plain.data());
        for (size_t d = 0; d < count; ++d) {
          SCOPED_TRACE("n " + std::to_string(n) + " count " + std::to_string(count) + " d " +
                       std::to_string(d) + " sign " + std::to_string(sign));
          Eigen::Index one = 0;
          const double want = sign > 0 ? s.max_dot(v[d], &one) : -s.min_dot(v[d], &one);
          EXPECT_EQ(out[d], want);  // bit for bit: the sampling's gaps must not change
          EXPECT_EQ(plain[d], want);
          EXPECT_EQ(at[d], one);
        }
      }
    }
  }
}
