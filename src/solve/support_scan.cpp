#include "solve/support_scan.h"

#include <algorithm>
#include <limits>

namespace pd {

SoaPoints::SoaPoints(const Points& x)
    : x_(x.row(0).begin(), x.row(0).end()),
      y_(x.row(1).begin(), x.row(1).end()),
      z_(x.row(2).begin(), x.row(2).end()) {}

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

}  // namespace pd
