// The eight corners of an axis-aligned box: the test suites' simplest polytope.
#pragma once

#include "geometry/types.h"

namespace pd_test {

inline pd::Points box_points(const pd::Vec3& lo, const pd::Vec3& hi) {
  pd::Points p(3, 8);
  for (int k = 0; k < 8; ++k)
    p.col(k) = pd::Vec3(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
  return p;
}

}  // namespace pd_test
