// Exact tests between two triangle meshes (not their hulls): do the parts
// share a point, and how deep does one's deepest vertex sit inside the other.
// CGAL lives in mesh_intersect.cpp only.
#pragma once

#include <array>
#include <limits>
#include <memory>
#include <vector>

#include "geometry/mesh.h"
#include "geometry/ray_parity.h"
#include "geometry/types.h"

namespace pd {

/// A mesh made ready for the exact tests: vertices with equal coordinates
/// merged, search trees built. Build it once per part and reuse it for every
/// pair; it is immutable and may be queried from several threads.
///
/// Closed means every edge is shared by an even number of triangles (after the
/// merge), so the mesh bounds a solid by the even-odd rule (a housing with an
/// inner cavity shell is a solid with a void). Open meshes have a surface only.
/// Vertices no triangle uses (points, lines) take no part in any test.
/// Throws std::invalid_argument when the mesh has no triangles, a triangle
/// index is out of range or a coordinate is not finite.
class PreparedMesh {
 public:
  explicit PreparedMesh(const Mesh& mesh);
  ~PreparedMesh();
  PreparedMesh(PreparedMesh&&) noexcept;
  PreparedMesh& operator=(PreparedMesh&&) noexcept;

  bool closed() const;
  /// Closed, every edge used as often u→v as v→u, enclosed volume > 0: each
  /// face's corners run counter-clockwise seen from outside the solid.
  bool oriented() const;
  int shells() const;  ///< connected components (triangles sharing a vertex)
  /// Some triangles are degenerate (kept as segments): a face list is not the whole surface.
  bool has_segments() const;
  /// Signed distance to the surface: > 0 strictly inside the closed mesh
  /// (even-odd rule), else minus the distance; the nearest surface point in
  /// *nearest and its face's unit normal (from the corners' order; zero when
  /// the nearest is a degenerate triangle) in *face_normal. On open meshes it
  /// is never positive. `near_face`, when given, is a face tried first (a
  /// nearby query's, -1 for none) and gets this query's: the same answer,
  /// found sooner in a run of nearby queries.
  double signed_distance(const Vec3& p, Vec3* nearest = nullptr, Vec3* face_normal = nullptr,
                         int* near_face = nullptr) const;
  /// The distance to the surface, with the same nearest point, normal and
  /// `near_face` as signed_distance, but no inside test (for callers that
  /// decide inside another way: a union of shells). `side_of_face`, when
  /// given, gets the side of the nearest face p lies on where that face alone
  /// says it (the nearest point strictly inside it): +1 the side its normal
  /// points to, -1 the other, 0 when it cannot say. Whatever the mesh's
  /// orientation: p lies on that side of every closed shell the face is of.
  double unsigned_distance(const Vec3& p, Vec3* nearest, Vec3* face_normal,
                           int* near_face = nullptr, int* side_of_face = nullptr) const;
  /// p's side of each of several closed shells made of this mesh's faces (face
  /// f is of shell face_shell[f], 0 <= face_shell[f] < shells), written to
  /// sides[0 … shells − 1]: one ray for them all (ray_parity_sides).
  void shell_sides(const Vec3& p, const std::vector<int>& face_shell, RaySide* sides,
                   size_t shells) const;
  /// Every (non-degenerate) face that meets the box {origin + R·y : lo <= y <=
  /// hi} (R a rotation), and perhaps some others near it, appended to `out` in
  /// increasing order; past `limit` of them, limit + 1 in no order
  /// (TriangleTree::in_turned_box).
  void faces_in_turned_box(const Eigen::Matrix3d& R, const Vec3& origin, const Vec3& lo,
                           const Vec3& hi, std::vector<int>& out,
                           size_t limit = std::numeric_limits<size_t>::max()) const;
  /// Corners of face i (0 <= i < faces()), in the mesh's order.
  std::array<Vec3, 3> face(int i) const;
  int faces() const;
  /// The faces' axes (geometry/face_axes.h); the identity without faces.
  Eigen::Matrix3d face_axes() const;
  /// Distance from p to the surface (the nearest triangle), scene units.
  double distance(const Vec3& p) const;
  /// The point of the surface nearest to p.
  Vec3 closest_point(const Vec3& p) const;
  /// p strictly inside the closed mesh (even-odd rule); always false when open.
  bool inside(const Vec3& p) const;
  /// p strictly outside the closed mesh (not on its surface); always false when open.
  bool outside(const Vec3& p) const;
  /// Distance from p to the part: 0 strictly inside a closed mesh, else the
  /// distance to the surface. On consistently oriented closed meshes the side
  /// of the nearest face decides when the nearest point is inside that face
  /// (exact then: the segment to it crosses no other face); the ray test only
  /// at edges and vertices, or when orientation is unknown.
  double outside_distance(const Vec3& p) const;

  /// Where the previous of a run of nearby queries ended: the next one tries
  /// that face first, so its search starts with a near bound (the same answer,
  /// found faster when the queries are close, as the samples of a lattice are).
  /// Also the last query point found strictly inside: a query joined to it by
  /// a segment that meets no face is inside too (parity cannot change), which
  /// a short segment's test tells far faster than a nearest-face search.
  struct Hint {
    Vec3 point = Vec3::Zero();
    long face = -1;  ///< -1: none yet
    Vec3 inside_point = Vec3::Zero();
    bool has_inside = false;
  };
  double outside_distance(const Vec3& p, Hint& hint) const;

  struct Impl;
  const Impl& impl() const { return *impl_; }

 private:
  // The distance and nearest point of signed_distance; with `side`, also the
  // side of the nearest face p lies on (unsigned_distance's side_of_face).
  double nearest_on_surface(const Vec3& p, Vec3* nearest, Vec3* face_normal, int* near_face,
                            int* side) const;
  std::unique_ptr<Impl> impl_;
};

/// Whether the parts share a point: a surface of a meets a surface of b (exact
/// predicates on the double coordinates, so touching counts as intersecting:
/// a bolt whose faces lie on the hole's faces intersects it), or a shell of one
/// lies inside the other's closed mesh (containment, even-odd rule). With an
/// open mesh only its surface counts: a part inside an open shell is not found.
/// Degenerate (zero-area) triangles take part as segments. Never throws on
/// self-intersecting meshes: their inside is the even-odd one, so a part in
/// the overlap of two overlapping shells of one mesh counts as outside.
bool meshes_intersect(const PreparedMesh& a, const PreparedMesh& b);
/// Whether a surface of a meets a surface of b (exact; touching counts); no containment test.
bool surfaces_meet(const PreparedMesh& a, const PreparedMesh& b);
bool meshes_intersect(const Mesh& a, const Mesh& b);

/// A lower bound of the pair's penetration depth from single vertices: a vertex
/// p of a strictly inside closed b must leave b, so any translation separating
/// the parts is at least p's distance to b's surface long (and vice versa).
struct MeshDepthBound {
  double depth = 0.0;  ///< scene units; 0 when no vertex lies strictly inside
  /// Unit; the DepthSolution convention (solve/result.h): moving b by
  /// depth·direction lifts the realising vertex out: (p − q)/|p − q| for p of a
  /// with closest point q on b's surface, (q − p)/|q − p| for p of b in a.
  Vec3 direction = Vec3::UnitZ();
  int vertex = -1;                    ///< the realising vertex's column in its Mesh; -1 if none
  bool vertex_of_a = true;            ///< the realising vertex belongs to a (inside b) or to b
  Vec3 surface_point = Vec3::Zero();  ///< q, its closest point on the other surface
  bool tested_in_a = false, tested_in_b = false;  ///< whether a (b) was closed: if not,
                                                  ///< no vertex could be inside it
};

/// Max over the vertices of a strictly inside closed b (even-odd rule) of their
/// distance to b's surface, and vice versa. Open meshes contain no vertex (the
/// corresponding tested_in_* is false). The distance is to the nearest triangle,
/// so on a self-intersecting mesh it can only be smaller: still a lower bound.
MeshDepthBound deepest_vertex_depth(const PreparedMesh& a, const PreparedMesh& b);
MeshDepthBound deepest_vertex_depth(const Mesh& a, const Mesh& b);

}  // namespace pd
