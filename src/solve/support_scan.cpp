#include "solve/support_scan.h"

#include <algorithm>
#include <limits>

namespace pd {

SoaPoints::SoaPoints(const Points& x) : x_(x.cols()), y_(x.cols()), z_(x.cols()) {
  // Column by column: a row iterator of an empty matrix offsets a null pointer.
  for (Eigen::Index k = 0; k < x.cols(); ++k) {
    x_[k] = x(0, k);
    y_[k] = x(1, k);
    z_[k] = x(2, k);
  }
}

double SoaPoints::max_dot(const Vec3& v, Eigen::Index* index) const {
  using Arr = Eigen::Array<double, Eigen::Dynamic, 1>;
  constexpr Eigen::Index kBlock = 64;
  alignas(64) double buf[kBlock];
  double best = -std::numeric_limits<double>::infinity();
  Eigen::Index at = 0;
  const Eigen::Index n = size();
  for (Eigen::Index b = 0; b < n; b += kBlock) {
    const Eigen::Index m = std::min(kBlock, n - b);
    Eigen::Map<Arr> s(buf, m);
    s = Eigen::Map<const Arr>(x_.data() + b, m) * v.x() +
        Eigen::Map<const Arr>(y_.data() + b, m) * v.y() +
        Eigen::Map<const Arr>(z_.data() + b, m) * v.z();
    const double block_max = s.maxCoeff();
    if (block_max > best) {  // ties keep the earlier block: the first index wins
      best = block_max;
      at = b + static_cast<Eigen::Index>(std::find(buf, buf + m, block_max) - buf);
    }
  }
  if (index) *index = at;
  return best;
}

void SoaPoints::max_dots(const Vec3* v, size_t count, double sign, double* out,
                         Eigen::Index* index) const {
  constexpr size_t kBlock = 32;
  alignas(64) double dx[kBlock], dy[kBlock], dz[kBlock], best[kBlock];
  alignas(64) Eigen::Index at[kBlock];
  const size_t n = x_.size();
  for (size_t b = 0; b < count; b += kBlock) {
    const size_t m = std::min(kBlock, count - b);
    for (size_t d = 0; d < kBlock; ++d) {
      // Negation is exact, so sign·v gives max_dot(−v)'s products bit for bit;
      // the unused tail of a block computes zeros that are never read.
      const Vec3 u = d < m ? Vec3(sign * v[b + d]) : Vec3::Zero();
      dx[d] = u.x();
      dy[d] = u.y();
      dz[d] = u.z();
      best[d] = -std::numeric_limits<double>::infinity();
      at[d] = 0;
    }
    // The sum in max_dot's order, (x·vx + y·vy) + z·vz: the same rounding.
    if (index) {
      for (size_t i = 0; i < n; ++i) {
        const double xi = x_[i], yi = y_[i], zi = z_[i];
        for (size_t d = 0; d < kBlock; ++d) {
          const double s = xi * dx[d] + yi * dy[d] + zi * dz[d];
          at[d] = s > best[d] ? static_cast<Eigen::Index>(i) : at[d];  // the first index wins
          best[d] = s > best[d] ? s : best[d];
        }
      }
      std::copy(at, at + m, index + b);
    } else {
      for (size_t i = 0; i < n; ++i) {
        const double xi = x_[i], yi = y_[i], zi = z_[i];
        for (size_t d = 0; d < kBlock; ++d) {
          const double s = xi * dx[d] + yi * dy[d] + zi * dz[d];
          best[d] = s > best[d] ? s : best[d];
        }
      }
    }
    std::copy(best, best + m, out + b);
  }
}

}  // namespace pd
