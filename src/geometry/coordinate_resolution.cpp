#include "geometry/coordinate_resolution.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace pd {

double coordinate_step(double magnitude, bool float32) {
  const int digits = float32 ? FLT_MANT_DIG : DBL_MANT_DIG;  // 24, 53 (with the hidden bit)
  const double smallest = float32 ? FLT_MIN : DBL_MIN;
  const double m = std::max(std::fabs(magnitude), smallest);
  int e = 0;
  std::frexp(m, &e);  // m = f · 2^e, f in [0.5, 1): the leading bit is 2^(e − 1)
  return std::ldexp(1.0, e - digits);
}

double coordinate_resolution(double max_abs, bool float32, double stretch, double placed_max_abs) {
  return std::max(coordinate_step(max_abs, float32) * stretch,
                  coordinate_step(placed_max_abs, false));
}

double max_abs_coordinate(const Points& p) {
  return p.size() ? p.cwiseAbs().maxCoeff() : 0.0;
}

}  // namespace pd
