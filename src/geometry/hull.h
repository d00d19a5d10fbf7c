// Convex hulls with qhull's reentrant library (libqhull_r).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "geometry/types.h"

namespace pd {

/// The extreme points of a point set. Degenerate input is not an error: a flat
/// set keeps its 2-D hull polygon, a collinear one its two end points, a single
/// point itself. Every case keeps original input coordinates.
struct Hull {
  Points vertices;    ///< the extreme points, in input coordinates
  int dimension = 3;  ///< 3 solid, 2 flat, 1 collinear, 0 a single point
  std::vector<std::string> warnings;
};

/// Throws std::invalid_argument for an empty set or non-finite coordinates.
Hull convex_hull(const Points& pts);

/// The hull of points known to be the vertices of a solid hull, moved by an
/// affine map (a file's hull placed in the scene): a nonsingular affine image
/// of a hull's vertices is its image's, so no qhull runs again while the set
/// is still solid by convex_hull's own test; else convex_hull of them.
Hull hull_of_hull_vertices(const Points& pts);

/// The triangulated facets of a solid hull as convex_hull found them: corners
/// as indices into Hull::vertices, outward unit normals in the input's axes.
struct HullTriangles {
  std::vector<std::array<int, 3>> triangles;
  std::vector<Vec3> normals;
};
/// The same, with the facets of the same qhull run into `facets` when the
/// hull is solid (dimension 3; else `facets` is left empty).
Hull convex_hull(const Points& pts, HullTriangles* facets);

/// A triangulated 3-D hull with outward unit normals and their planes: each
/// facet satisfies normal·x + offset <= 0 for every point of the hull
/// (triangles index the input points).
struct HullFacets : HullTriangles {
  std::vector<double> offsets;
};

/// Facets of the hull of a full-dimensional point set; returns false (and leaves
/// `out` empty) when qhull finds the set flat.
bool hull_facets(const Points& pts, HullFacets& out);

}  // namespace pd
