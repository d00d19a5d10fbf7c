// Support values max_i x_i·v without a temporary: the hot loop of the sampling
// and the certificate's grid (864 directions × (n + m) points per pair).
//
// Eigen's v^T·P writes a row of n values to a fresh heap block before its
// max is taken (a malloc per evaluation, which dominates at 8–40 vertices), and
// its argmax visitor is scalar. Here the coordinates are stored as three arrays,
// so a block of 64 values is computed and reduced with SIMD on the stack, and
// the index is looked for only in a block that raised the maximum.
#pragma once

#include <vector>

#include "geometry/types.h"

namespace pd {

/// The points of a Points matrix as three coordinate arrays.
class SoaPoints {
 public:
  explicit SoaPoints(const Points& x);
  Eigen::Index size() const { return static_cast<Eigen::Index>(x_.size()); }

  /// max_i x_i·v and the first index reaching it (-inf and 0 when empty).
  double max_dot(const Vec3& v, Eigen::Index* index = nullptr) const;
  /// min_i x_i·v and the first index reaching it: −max_i x_i·(−v), exactly
  /// (negation is exact in floating point).
  double min_dot(const Vec3& v, Eigen::Index* index = nullptr) const { return -max_dot(-v, index); }

  /// max_dot(sign·v[d]) for each of `count` directions, bit for bit, with the
  /// first index reaching it when `index` is given. One pass over the points per
  /// block of directions, vectorised across the directions: on small sets (the
  /// common contact of two 8-vertex boxes) a per-direction scan is all overhead.
  /// sign is +1 or −1 (then −out[d] is min_dot(v[d])).
  void max_dots(const Vec3* v, size_t count, double sign, double* out,
                Eigen::Index* index = nullptr) const;

 private:
  std::vector<double> x_, y_, z_;
};

}  // namespace pd
