// The geometry an HTML report shows: each part as a small triangle mesh, the
// realising pieces, and the overlap of two convex sets. Display only: what is
// decimated says how, in `how`.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "geometry/hull.h"
#include "geometry/mesh.h"
#include "scene/parts.h"

namespace pd {

/// Triangles for a browser: vertices relative to `origin` (float precision is
/// then relative to the part's size, not to its distance from the scene origin).
struct WebMesh {
  Vec3 origin = Vec3::Zero();
  std::vector<float> positions;  ///< x, y, z per vertex, relative to origin
  std::vector<std::array<unsigned, 3>> triangles;
  std::string how;  ///< e.g. "mesh, 1,204 triangles" or "hull of 400 of 12,000 hull vertices"

  size_t vertex_count() const { return positions.size() / 3; }
};

/// A part as at most `max_triangles` triangles: its placed surface mesh when it
/// has one (nonconvex parts), decimated by vertex clustering when too large;
/// else its convex pieces' hulls; past the cap, the hull of all its vertices,
/// and past it again the hull of an even subsample of those. Empty for a part
/// that has no geometry (an unusable part).
WebMesh part_web_mesh(const Part& part, size_t max_triangles);

/// The hull of one convex piece (points, segments and flat pieces included:
/// flat ones as their triangulated polygon, lower ones as nothing).
WebMesh hull_web_mesh(const Points& vertices, size_t max_triangles);

/// The convex pieces realising a pair's depth ([i, j] of the report), when the
/// parts hold them: the decomposition's pieces when one was made, else the
/// part's own pieces.
const Hull* realising_piece(const Part& part, int index);
/// How many pieces realising_piece() chooses from.
size_t piece_count(const Part& part);

/// The overlap of two convex point sets' hulls (geometry/convex_overlap.h) as a
/// web mesh of at most `max_triangles`; nullopt when they do not overlap in a solid.
std::optional<WebMesh> overlap_web_mesh(const Points& a, const Points& b, size_t max_triangles);

/// The overlap of two parts' own solids, where a part is nonconvex (its placed
/// surface mesh; a convex part is its convex pieces): each part's surface
/// triangles that lie inside the other part, the boundary of the intersection.
/// Within the parts' common box, a triangle whose corners lie on one side of
/// the other part is kept or dropped whole once it is an 8th of that box's
/// diagonal, and one that crosses its surface is split to a 48th and kept by
/// its pieces' centres (a jagged edge at that scale, as drawn). `mesh` is
/// empty when the parts do not overlap in a solid or when it
/// cannot be drawn cheaply; `note` then says why (a mesh that bounds no solid,
/// more than tol::kHtmlOverlapProbes inside tests).
struct SolidOverlap {
  std::optional<WebMesh> mesh;
  std::string note;
};
SolidOverlap solid_overlap_web_mesh(const Part& a, const Part& b, size_t max_triangles);

/// Every vertex of a part (all pieces), placed.
Points part_vertices(const Part& part);

/// Standard base64 of raw bytes (the page decodes typed arrays from it).
std::string base64(const void* data, size_t bytes);

}  // namespace pd
