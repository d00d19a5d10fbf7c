// How far a part is from its convex hull, measured once per mesh: the
// pipeline keeps a part's hull as its single piece when it is convex within a
// concavity tolerance, and decomposes it otherwise.
#pragma once

#include <cmath>
#include <vector>

#include "geometry/hull.h"
#include "geometry/mesh.h"
#include "geometry/types.h"

namespace pd {

class PreparedMesh;
class SurfacePolygons;

/// Estimated concavity of a point set's hull against a part: the largest
/// distance from a point of hull(points) to the part (its closed solid, or its
/// surface when open), in scene units. Sampled: a lattice on the hull's facets
/// (about `samples` points in all), the projections of `surface` points (the
/// part's vertices there) onto their nearest hull facet (so a shallow notch
/// between lattice points is still measured at its deepest vertex), and, when
/// the hull encloses more than a ball of radius `void_radius` of volume the
/// part does not fill, a grid inside the hull (enclosed voids). The true value
/// can exceed the estimate by about `resolution` (the lattice spacing), never
/// fall below it. `witness` is the sample realising it, `closest` its nearest
/// point on the part.
/// The lattice's sample count of a mesh's measurement (part of its cache key).
inline constexpr int kConvexitySamples = 4000;

struct Concavity {
  double value = 0.0;
  double resolution = 0.0;
  Vec3 witness = Vec3::Zero(), closest = Vec3::Zero();
  bool stopped = false;  ///< stopped above hull_concavity's `stop_above`: a lower bound
};
/// The facets of hull(points), computed on the points centred at their mean
/// (as hull_concavity measures them): made once when one point set gets several
/// estimates (a screen, then the full one) and its volume, the same qhull run
/// each would make.
struct HullOfPoints {
  Vec3 centre = Vec3::Zero();
  Points centred;  ///< the points − centre
  HullFacets f;
  std::vector<double> area;  ///< per facet
  double volume = 0.0, total_area = 0.0;
  bool facets = false;  ///< qhull found a solid hull (else the set is flat or smaller)
  /// A solid hull of positive volume: what an estimate needs (else value 0).
  bool solid() const { return facets && volume > 0; }
};
HullOfPoints hull_of_points(const Points& points);
/// The same from facets already found (convex_hull's, of these points:
/// corners index `points`, unit normals in their axes), without qhull.
HullOfPoints hull_of_points(const Points& points, const HullTriangles& facets);

/// `points` need at least 4 affinely independent points (else value 0: a flat
/// or smaller hull lies on the part). `missing_volume` is hull volume − the
/// part's volume inside the hull, or a negative value when unknown (then the
/// interior grid always runs). The estimate stops as soon as it exceeds
/// `stop_above`: then `value` is only a lower bound, above that threshold
/// (enough to call the part nonconvex at any tolerance up to it), and
/// `stopped` is set.
/// `on_part`, when given, holds polygons lying on the part (within its
/// `within`): a sample they cover is not measured, which changes the estimate
/// only where it is at most `within` (the value and witness of an estimate
/// above it are the same).
Concavity hull_concavity(const Points& points, const PreparedMesh& part, double void_radius,
                         double missing_volume, const Points& surface,
                         int samples = kConvexitySamples, double stop_above = INFINITY,
                         const SurfacePolygons* on_part = nullptr);
/// The same on hull_of_points(points).
Concavity hull_concavity(const HullOfPoints& hull, const PreparedMesh& part, double void_radius,
                         double missing_volume, const Points& surface,
                         int samples = kConvexitySamples, double stop_above = INFINITY,
                         const SurfacePolygons* on_part = nullptr);

/// The rounding noise of a mesh's coordinates: float32 files far from the
/// origin hold them to ~2^-24 of their magnitude (8 units of it), and at least
/// 1e-9 of the mesh's size. `vertices` as read (before centring).
double coordinate_noise(const Points& vertices);

/// The polygons of m's triangles (for hull_concavity's `on_part`).
SurfacePolygons triangle_polygons(const Mesh& m, double within);

/// A mesh's nonconvexity (scene units throughout).
struct Convexity {
  bool closed = false;       ///< every edge shared by an even number of triangles
  int shells = 0;            ///< connected components
  double volume = 0.0;       ///< enclosed volume (closed meshes; 0 when open)
  double hull_volume = 0.0;  ///< volume of the convex hull of the vertices
  double hull_area = 0.0;
  /// (hull_volume − volume) / hull_area: the mean thickness of what the hull
  /// adds to the part (a cheap screen; 0 for open meshes, where volume is unknown).
  double screen = 0.0;
  Concavity concavity;  ///< of the whole mesh's hull against the mesh
  bool convex = false;  ///< concavity.value <= the tolerance: the hull is the part
  /// More than one shell, none inside another, each convex within the
  /// tolerance: the pieces are the shells (a part in the gap between two
  /// shells is not in the mesh's material, but is in its hull).
  bool shells_convex = false;
  /// Some shell lies inside another (a cavity): measured only when not convex.
  bool nested_shells = false;
};

/// What the parts stage needs of a mesh: whether it is closed, and its
/// concavity (as hull_concavity, with the void radius `concavity_tol`),
/// estimated only until it exceeds `stop_above` (then a lower bound: the
/// part is nonconvex at every tolerance up to `stop_above`). `hull_points`,
/// when given, are the extreme points of m's vertices (the parts stage has
/// them already): the hull is built from them, not from every corner again.
struct ConvexityScreen {
  bool closed = false;
  Concavity concavity;
};
ConvexityScreen screen_convexity(const Mesh& m, double concavity_tol, double stop_above,
                                 const Points* hull_points = nullptr,
                                 const HullTriangles* hull_facets = nullptr);
/// The same with m's prepared mesh given (a caller that keeps one for later
/// queries builds it once), and the hull's facets when the caller has them
/// (of `hull_points`, as hull_of_points takes them).
ConvexityScreen screen_convexity(const Mesh& m, const PreparedMesh& part, double concavity_tol,
                                 double stop_above, const Points* hull_points = nullptr,
                                 const HullTriangles* hull_facets = nullptr);

/// Measures m once. A convex (within concavity_tol) single-shell mesh is its
/// own piece. Open meshes: the concavity is against the surface, volume 0.
/// Coordinates are centred before any arithmetic (parts sit at x ≈ 20,000 mm).
/// The whole mesh's estimate stops above `stop_above` (as hull_concavity's:
/// then concavity.value is a lower bound and concavity.stopped is set); at
/// `stop_above` = concavity_tol every flag is what the full estimate gives.
Convexity measure_convexity(const Mesh& m, double concavity_tol, double stop_above = INFINITY);

/// The connected components of m (triangles sharing a vertex; vertices with
/// equal coordinates are one), each with its own compact vertex list.
std::vector<Mesh> mesh_shells(const Mesh& m);

/// The triangle columns of each connected component of m, in column order.
std::vector<std::vector<int>> shell_triangles(const Mesh& m);

/// Enclosed volume of a closed, consistently oriented mesh (absolute value of
/// the divergence sum, computed about the vertices' centre).
double mesh_volume(const Mesh& m);

}  // namespace pd
