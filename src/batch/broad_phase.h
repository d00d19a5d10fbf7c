// Broad phase: which part pairs can touch at all.
#pragma once

#include <utility>
#include <vector>

#include "geometry/aabb.h"

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

}  // namespace pd
