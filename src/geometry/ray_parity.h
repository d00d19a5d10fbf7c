// Which side of a closed triangle soup a point lies on, by the parity of a
// ray's crossings (even-odd rule), with exact predicates. The rays run along
// the coordinate axes over the soup's own TriangleTree, so an inside test needs
// no second search structure and visits only the boxes the ray pierces.
#pragma once

#include <optional>
#include <vector>

#include "geometry/triangle_tree.h"
#include "geometry/types.h"

namespace pd {

enum class RaySide { kOutside, kOnSurface, kInside };

/// p's side of the soup in `tree` (whose corners lie in the box [lo, hi]),
/// counted on a ray from p that leaves the box. A ray through an edge or a
/// vertex, or lying in a triangle's plane, proves nothing: the next is tried —
/// the six axis directions, shortest way out first, then fixed oblique ones.
/// Exact (CGAL's filtered predicates on the double coordinates), so the answer
/// does not depend on which ray decided it. On an open soup the parity means
/// nothing; callers test closedness first.
RaySide ray_parity_side(const TriangleTree& tree, const Vec3& lo, const Vec3& hi, const Vec3& p);

/// p's side of each of several closed soups held in one tree (triangle i
/// belongs to soup label[i], 0 <= label[i] < soups; their corners lie in
/// [lo, hi]), written to sides[0 … soups − 1]: one ray decides them all, where
/// a test per soup casts one each (the shells of a multi-body part). Each side
/// is the one ray_parity_side gives for that soup's tree alone.
void ray_parity_sides(const TriangleTree& tree, const std::vector<int>& label, const Vec3& lo,
                      const Vec3& hi, const Vec3& p, RaySide* sides, size_t soups);

/// p's side counted on the one ray from p along `direction` (nonzero), or
/// nothing when that ray meets an edge, a vertex or lies in a triangle's plane
/// before deciding: the step ray_parity_side repeats until a ray decides.
std::optional<RaySide> ray_parity_along(const TriangleTree& tree, const Vec3& lo, const Vec3& hi,
                                        const Vec3& p, const Vec3& direction);

/// Whether the closed segment [a, b] meets (crosses or touches) a triangle of
/// the tree: exact.
bool segment_meets_triangles(const TriangleTree& tree, const Vec3& a, const Vec3& b);

}  // namespace pd
