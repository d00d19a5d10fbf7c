#include "results/certified_decimal.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace pd {

double certified_decimal(double lower, double upper) {
  if (!(lower <= upper) || !std::isfinite(lower) || !std::isfinite(upper)) return lower;
  if (lower <= 0 && upper >= 0) return 0.0;
  // With n significant digits the decimals are a grid; when any of them lies in
  // the bracket, the one nearest its middle does (it is at most half the
  // bracket's width from the middle), so the middle rounded to n digits is the
  // candidate. At 17 digits the middle itself is one.
  const double mid = lower + 0.5 * (upper - lower);
  char buf[40];
  for (int n = 1; n <= 17; ++n) {
    std::snprintf(buf, sizeof buf, "%.*e", n - 1, mid);
    const double c = std::strtod(buf, nullptr);
    if (c >= lower && c <= upper) return c;
  }
  return mid;
}

}  // namespace pd
