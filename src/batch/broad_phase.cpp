#include "batch/broad_phase.h"

#include <algorithm>
#include <numeric>

#include "batch/motion_sweep.h"

namespace pd {

bool boxes_touch(const Aabb& a, const Aabb& b, double margin) {
  for (int k = 0; k < 3; ++k)
    if (!(a.lo[k] - b.hi[k] <= margin && b.lo[k] - a.hi[k] <= margin)) return false;
  return true;
}

std::vector<std::pair<int, int>> overlapping_boxes(const std::vector<Aabb>& boxes, double margin) {
  const int n = static_cast<int>(boxes.size());
  std::vector<std::pair<int, int>> out;
  if (n < 2) return out;
  // Sweep along the axis where the box centres spread most: fewest false candidates.
  const int axis = widest_spread_axis(boxes);
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return boxes[a].lo[axis] < boxes[b].lo[axis] ||
           (boxes[a].lo[axis] == boxes[b].lo[axis] && a < b);
  });
  std::vector<int> active;  // boxes whose interval may still reach the sweep line
  for (int i : order) {
    // Boxes sorted by lo: a gap beyond the margin now stays beyond it for every
    // later box (the rounded difference is monotone), so j can leave the list.
    active.erase(
        std::remove_if(active.begin(), active.end(),
                       [&](int j) { return !(boxes[i].lo[axis] - boxes[j].hi[axis] <= margin); }),
        active.end());
    for (int j : active)
      if (boxes_touch(boxes[i], boxes[j], margin)) out.emplace_back(std::min(i, j), std::max(i, j));
    active.push_back(i);
  }
  std::sort(out.begin(), out.end());
  return out;
}

double broad_phase_reach(const Checks& checks) {
  double reach = 0.0;
  if (checks.clearance) {
    reach = checks.clearance->min;
    for (const auto& e : checks.clearance->pairs) reach = std::max(reach, e.min);
    reach = std::max(reach, checks.clearance->rules_reach);
  }
  return reach;
}

Aabb culling_box(const Part& part, const Checks& checks) {
  return checks.motion ? swept_box(part, checks.motion->grid) : part.box;
}

int widest_spread_axis(const std::vector<Aabb>& boxes) {
  if (boxes.empty()) return 0;
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const auto& b : boxes) {
    const Vec3 c = 0.5 * (b.lo + b.hi);
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  return axis;
}

}  // namespace pd
