// A circle's chord sag, and a part as build_parts makes it under tolerance
// auto (its measured sag and box): the tolerance-auto suites' fixtures.
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "geometry/tessellation_sag.h"
#include "scene/parts.h"

namespace pd_test {

/// How far a chord of a circle of radius r cut in `segments` lies inside it.
inline double chord_sag(int segments, double r) {
  return r * (1 - std::cos(M_PI / segments));
}

inline pd::Part sag_part(const std::string& id, const pd::Mesh& m,
                         std::optional<double> declared = {}) {
  pd::Part p;
  p.id = id;
  p.box = pd::Aabb::of(m.vertices);
  pd::PartSag s;
  s.measured = pd::measure_tessellation_sag(m, pd::CoordinateStorage::kDouble);
  s.declared = declared;
  p.sag = s;
  return p;
}

}  // namespace pd_test
