// Broad phase: which part pairs can touch at all.
#pragma once

#include <utility>
#include <vector>

#include "geometry/aabb.h"
#include "scene/parts.h"
#include "scene/scene.h"

namespace pd {

/// Whether boxes a and b, one inflated by `margin`, overlap (touching counts):
/// per axis the gap lo − hi on both sides is at most `margin`. A pure function of
/// the two boxes (symmetric, exact differences), so a shard that tests only its
/// own pairs decides each exactly as the whole scene's sweep does.
bool boxes_touch(const Aabb& a, const Aabb& b, double margin);

/// Pairs (i < j) whose boxes, inflated by `margin`, overlap (touching counts).
/// Sort and sweep along the axis of largest spread: O(n log n + k) for k
/// overlapping pairs on x, never a loop over all n² pairs. Sorted by (i, j).
std::vector<std::pair<int, int>> overlapping_boxes(const std::vector<Aabb>& boxes, double margin);

/// n(n − 1)/2: the pairs of `parts` parts.
inline long pair_count(long parts) {
  return parts * (parts - 1) / 2;
}

/// How far apart boxes may be and still need a check: the largest clearance asked.
double broad_phase_reach(const Checks& checks);

/// The box the broad phase culls a usable part by: the box a moving part sweeps
/// over the time grid, else its hull's box.
Aabb culling_box(const Part& part, const Checks& checks);

/// The axis (0, 1, 2) along which the boxes' centres spread most; 0 when there
/// are none.
int widest_spread_axis(const std::vector<Aabb>& boxes);

}  // namespace pd
