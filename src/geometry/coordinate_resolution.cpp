#include "geometry/coordinate_resolution.h"

#include <cmath>

namespace pd {

double coordinate_resolution(const Points& points, CoordinateStorage storage) {
  if (points.cols() == 0) return 0.0;
  const double largest = points.cwiseAbs().maxCoeff();
  if (!(largest > 0.0) || !std::isfinite(largest)) return 0.0;
  int exponent = 0;
  std::frexp(largest, &exponent);  // largest = m · 2^exponent, m in [0.5, 1)
  const int mantissa_bits = storage == CoordinateStorage::kFloat32 ? 24 : 53;
  // The step of numbers in [2^(exponent-1), 2^exponent).
  return std::ldexp(1.0, exponent - mantissa_bits);
}

}  // namespace pd
