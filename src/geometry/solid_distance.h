// Signed distance to a part's solid, with what the overlap thickness needs to
// bound it soundly: the distance from inside (exact, or a lower bound where a
// multi-body file's shells meet) and, around a region, the local plane
// structure of the surface that bounds the distance from above.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "geometry/mesh.h"
#include "geometry/mesh_intersect.h"
#include "geometry/types.h"
#include "tolerances.h"

namespace pd {

/// Bounds of the signed distance sd(p) = d(p, complement) inside, −d(p, solid)
/// outside. Outside a closed solid both bounds are the exact −distance.
struct DistanceBounds {
  double lower = 0.0;
  double upper = 0.0;  ///< +inf inside a solid whose inside distance is not known from above
  Vec3 nearest = Vec3::Zero();  ///< nearest point of the surface (every triangle)
};

/// A face plane: s(x) = offset − normal·x, positive on the solid's side
/// (`normal` points out of the solid, from the face's orientation).
struct FacePlane {
  Vec3 normal = Vec3::UnitZ();
  double offset = 0.0;
  double at(const Vec3& x) const { return offset - normal.dot(x); }
};

/// The surface near a box, as planes that bound the distance from inside from
/// above: for every point x of the box in the solid, min(sd(x), margin) is at
/// most each bound below, where the faces within the margin of the box are
/// all that were looked at (docs/solver.md, "Overlap thickness"). A bound that
/// would need a foot point farther than the margin is at least the margin, so
/// no foot point has to be kept anywhere.
/// - supporting planes: every face within the margin lies on their inner side,
///   so the solid's complement holds each one's outer side there, and
///   min(sd(x), margin) ≤ s_k(x) + slack for each k (a pin's facets, a plate's face);
/// - hole planes: the other faces' planes, when they bound a convex hole (each
///   such face on the outer side of the others' planes, every other face on the
///   inner side of one of them, normals within 60° of their mean m): the
///   complement then holds the intersection of their outer sides, and
///   min(sd(x), margin) ≤ kappa · (max_k s_k(x) + slack), kappa = 1 / cos(spread),
///   since moving x along m by that much leaves every outer side's boundary behind.
///   Where the normals spread wider (a small hole wholly near the box), m is
///   the mean of those facing the box, the hole keeps only the planes within 60°
///   of it, and the others are checked to stay behind every foot. Where the
///   other faces bound several holes (their planes grouped by facing each
///   other), each that passes these checks holds on its own: the solid near
///   the box lies outside each of them.
/// - wedges, where the other faces bound no convex hole (a pin's shank meeting
///   its head's underside: the complement is the union of one wedge per shank
///   facet): two planes whose outer sides' intersection W holds no face within
///   the margin and a point outside the solid (an exact ray test), so W is
///   complement there and min(sd(x), margin) ≤ kappa · (max(s_p(x), s_q(x)) +
///   slack) for each wedge, kappa = 1 / cos(half the angle between their normals).
/// All empty: nothing could be certified (degenerate faces, no orientation,
/// too many faces); the Lipschitz bound still holds.
struct LocalPlanes {
  /// One convex hole: sd(x) ≤ kappa · (max_k s_k(x) + slack) over its planes.
  struct Hole {
    std::vector<FacePlane> planes;
    double kappa = 1.0;
    double slack = 0.0;  ///< as `slack` below, measured for this hole
  };
  struct Wedge {
    FacePlane p, q;
    double kappa = 1.0;
    double slack = 0.0;  ///< as `slack` below, measured for this wedge
  };
  std::vector<FacePlane> supporting;
  /// Usually one; several where separate holes lie near the box (a drilled
  /// board's row of holes), each of which holds on its own.
  std::vector<Hole> holes;
  std::vector<Wedge> wedges;
  /// How far faces were measured to cross the supporting planes they should lie behind (the
  /// coordinates' rounding; accepted up to noise()): added to the bound, so it holds exactly.
  double slack = 0.0;
  /// The bounds hold for min(sd(x), margin), not for sd(x): the model looked
  /// at no face farther than the margin from its box, so it knows nothing
  /// where sd is at least that. A bound below the margin is a bound of sd;
  /// one at or above it says nothing.
  double margin = 0.0;
  bool empty() const { return supporting.empty() && holes.empty() && wedges.empty(); }
};

/// A frame of the caller's: the points x = origin + R·y, R a rotation.
struct RigidFrame {
  Vec3 origin = Vec3::Zero();
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Vec3 world(const Vec3& y) const { return origin + R * y; }
  Vec3 local(const Vec3& x) const { return R.transpose() * (x - origin); }
};

/// A box [lo, hi] of a frame's y; a model about it (SolidDistance::local_planes)
/// is in y.
struct FramedBox {
  RigidFrame frame;
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
};

/// The faces one run of SolidDistance::local_planes calls has taken into its
/// frame (their corners there, area vector and unit normal), kept so that each
/// face is taken there once: an overlap-thickness search asks about thousands
/// of nested boxes in one frame, and most faces near one box are near the next
/// (taking them in cost a third of its plane models). The values are those
/// the call would compute, so a model is the same with or without it. One per
/// search and part, on one thread; it follows the last mesh and frame asked.
class FrameFaces {
 public:
  struct Face {
    std::array<Vec3, 3> corners;
    Vec3 area;    ///< (b − a) × (c − a)
    Vec3 normal;  ///< area normalised; not finite for a degenerate face
  };
  /// Starts over unless `mesh` and `frame` are those of the faces kept.
  void use(const PreparedMesh& mesh, const RigidFrame& frame);
  /// Face f of the mesh and frame last given to use().
  const Face& operator[](int f);

 private:
  const PreparedMesh* mesh_ = nullptr;
  RigidFrame frame_;
  std::vector<int> slot_;  ///< per face of the mesh: its index in faces_ + 1, or 0
  std::vector<Face> faces_;
};

/// A closed triangle mesh as a solid. Vertices with equal coordinates are one
/// (shells as exported are welded by position). A mesh of several shells whose
/// surfaces do not meet is a solid by the even-odd rule (a housing with a
/// cavity); shells whose surfaces meet (a bolt exported as shank and head face
/// to face) are their union: inside any shell is inside, and the distance from
/// inside is known only from below (the shared faces are not surface).
/// Immutable after construction; queries may run on several threads.
class SolidDistance {
 public:
  /// Throws std::invalid_argument as PreparedMesh does (no triangles, bad index, NaN).
  explicit SolidDistance(const Mesh& mesh);

  /// A solid at all: closed (every edge used an even number of times).
  bool closed() const { return closed_; }
  /// Inside distances exact (no two shells' surfaces meet).
  bool exact() const { return exact_; }
  /// Why the distance from inside is not exact, or the solid not closed; empty when it is both.
  const std::string& note() const { return note_; }
  const Eigen::AlignedBox3d& box() const { return box_; }
  /// The whole surface, for the exact mesh tests (geometry/mesh_intersect.h).
  const PreparedMesh& mesh() const { return whole_; }
  /// The coordinates' rounding: the largest float32 half-step of any coordinate
  /// when the vertices are float32 values, else a few double ulps.
  double noise() const { return noise_; }
  /// The part's face axes (geometry/face_axes.h), a rotation R, and the box of
  /// Rᵀv over its faces' corners: the frame its pairs' overlap thickness
  /// splits space in (solve/overlap_thickness.h), found once per part.
  const Eigen::Matrix3d& axes() const { return axes_; }
  const Eigen::AlignedBox3d& box_in_axes() const { return box_in_axes_; }

  /// `near_face`: as PreparedMesh::signed_distance's, for a run of nearby
  /// queries. Without `upper`, the upper bound is left infinite inside a union
  /// (callers that read only the lower bound: it costs a ray test there).
  DistanceBounds at(const Vec3& p, int* near_face = nullptr, bool upper = true) const;

  /// The plane structure of the surface about a box of a frame, in that
  /// frame's coordinates: the planes of the faces within `margin` of the
  /// box, bounding min(sd, margin) (LocalPlanes). A long thin box about a
  /// seated face sees the faces near it, not all within its half-diagonal.
  /// `faces`, when given, keeps the faces taken into the frame for the next
  /// call (a search's nested boxes); the model is the same without it.
  LocalPlanes local_planes(const FramedBox& box, double margin, FrameFaces* faces = nullptr) const;

 private:
  // Union mode: inside some shell, and strictly outside every shell (exact ray
  // parity; one ray for all shells).
  bool inside_some_shell(const Vec3& p) const;
  // inside_some_shell, told first by p's nearest face (of the whole, `face`)
  // where it can: `side` is unsigned_distance's side_of_face.
  bool inside_union(const Vec3& p, int face, int side) const;
  bool outside_every_shell(const Vec3& p) const;

  PreparedMesh whole_;
  std::vector<PreparedMesh> shells_;  ///< union mode only: one per shell
  // Union mode: the shell each face of whole_ is of (whole_'s faces are the
  // shells' faces, so its tree serves their ray tests), and each shell's box in axes_.
  std::vector<int> shell_of_whole_face_;
  std::vector<Eigen::AlignedBox3d> shell_box_;
  bool closed_ = false, exact_ = true, oriented_ = false;
  std::string note_;
  Eigen::AlignedBox3d box_;
  double noise_ = 0.0;
  Eigen::Matrix3d axes_ = Eigen::Matrix3d::Identity();
  Eigen::AlignedBox3d box_in_axes_;
  double hair_ = 0.0;  ///< how far outside a face a union's complement is probed
};

/// A lower bound of a pair's penetration depth from one part's surface, which
/// needs no inside of that part (open meshes, thin sheets): a point p of a's
/// surface strictly inside closed b must leave b, so any separating translation
/// is at least sd_b(p) long. The largest sd_b over points sampled on a's faces
/// within b's box: every vertex there, then at most `max_samples` points inside
/// the faces (so it is never below the deepest vertex's bound). Where only a
/// depth above `only_above` would matter (a pair whose thickness search has
/// bracketed it, asking only whether a thin part decides it), pieces of faces
/// that cannot reach deeper are not split.
struct SurfaceDepth {
  double depth = 0.0;      ///< 0 when no sample lies strictly inside b
  Vec3 at = Vec3::Zero();  ///< the sample realising it
  /// Unit; the DepthSolution convention (solve/result.h): (p − q)/|p − q| for
  /// p of a with nearest point q on b's surface.
  Vec3 direction = Vec3::UnitZ();
};
SurfaceDepth surface_depth(const PreparedMesh& a, const SolidDistance& b,
                           long max_samples = tol::kSurfaceDepthSamples,
                           double only_above = -std::numeric_limits<double>::infinity());

}  // namespace pd
