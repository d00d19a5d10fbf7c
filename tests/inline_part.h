// A part of inline points as the batch layer gets it: its hull as the one
// piece and its box. For tests that solve pairs without a scene.
#pragma once

#include <string>

#include "geometry/hull.h"
#include "scene/parts.h"

namespace pd_test {

inline pd::Part inline_part(const std::string& id, const pd::Points& pts) {
  pd::Part p;
  p.id = id;
  p.source = "inline";
  p.pieces.push_back(pd::convex_hull(pts));
  p.box = pd::Aabb::of(p.pieces[0].vertices);
  return p;
}

}  // namespace pd_test
