#include <algorithm>

#include "scene/scene.h"
#include "tolerances.h"

namespace pd {

double AutoTolerance::band(double sa, double sb, double ra, double rb) const {
  double t = (sa + sb + ra + rb) * (1.0 + tol::kAutoToleranceMargin);
  if (min) t = std::max(t, *min);
  if (max) t = std::min(t, *max);
  return t;
}

}  // namespace pd
