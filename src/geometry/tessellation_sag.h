// How far a tessellated surface may lie from the surface it stands for: the
// chord sag of its smooth (tessellated) regions, measured from the mesh alone
// (docs/numerics.md, "Tessellation sag").
//
// When a mesh's vertices lie on the true surface (what CAD tessellators
// guarantee), a facet across a smooth crease of exterior angle θ deviates from
// the surface by s = (c/2)·tan(θ/4), c the facet's width across the crease:
// r(1 − cos(π/n)) for an n-segment cylinder of radius r. At a concave crease
// (a bore) the facets cut into the hole, so the mesh is larger than the part
// and two meshes may overlap by up to their concave sags where their true
// solids only touch; at a convex one (a pin) the mesh is smaller (gap
// artefacts). A facet of a doubly curved region (sphere, torus) deviates most
// inside it: its sag is also estimated from a quadratic patch through its
// corners with the corners' surface normals, and the smaller of the two
// estimates is kept (the patch is exact to 4 % for spheres and tori, the
// crease sum exact for developable cylinders and cones, whose apex normal the
// patch cannot know).
#pragma once

#include <vector>

#include "geometry/aabb.h"
#include "geometry/coordinate_resolution.h"
#include "geometry/mesh.h"

namespace pd {

/// How a part's coordinates were stored before pdcheck read them as doubles:
/// float32 for mesh files (assimp hands them over so), double for inline vertices.
enum class CoordinateStorage { kFloat32, kDouble };

/// A piece of a feature: its facets whose centroids fall in one cell of a grid
/// kSagPatchCells to the feature box's longest side. A revolved feature (a bore,
/// a fillet round a boss) has a box that holds its axis and everything inside
/// it; its patches lie along the surface, so a point can be near the feature's
/// surface, not merely inside its box (sag_at).
struct SagPatch {
  Aabb box;              ///< of the patch's facets' corners
  double concave = 0.0;  ///< the worst s⁺ of its facets
  double convex = 0.0;   ///< the worst s⁻ of its facets
};

/// One smooth region of a mesh: facets joined across tessellation creases
/// (dihedral angle at most kSagCreaseAngle), bounded by design edges (a box's
/// 90° edges) or the mesh's boundary. Regions with no sag (flat faces) are not
/// listed.
struct SagFeature {
  Aabb box;              ///< of the region's vertices (the mesh's coordinates)
  double concave = 0.0;  ///< s⁺: the most the mesh lies outside the surface (overlap artefacts)
  double convex = 0.0;   ///< s⁻: the most the mesh lies inside it (gap artefacts)
  double radius = 0.0;   ///< median radius of curvature across its creases
  int segments = 0;      ///< 2π / the median crease angle, rounded: segments per full turn
  long facets = 0;
  std::vector<SagPatch> patches;  ///< its facets by place, in the order of their grid cells
};

struct TessellationSag {
  std::vector<SagFeature> features;
  double concave = 0.0, convex = 0.0;  ///< the worst over the features
  double resolution = 0.0;             ///< coordinate_resolution of the mesh
  long creases = 0;                    ///< edges read as tessellation creases
  long design_edges = 0;               ///< sharp edges (and boundary or non-manifold ones)
};

/// Measures the sags of `m` (its coordinates; a float32 file's vertices as
/// read). Vertices at the same coordinates are welded first (STL repeats them
/// per triangle). Pure; linear in the mesh (one sort of its edges).
TessellationSag measure_tessellation_sag(const Mesh& m, CoordinateStorage storage);

/// The sags of the features whose box meets `near` (grown by `reach`), the
/// index of each worst one in `sag.features` (-1: none meets it).
struct LocalSag {
  double concave = 0.0, convex = 0.0;
  int concave_feature = -1, convex_feature = -1;
};
LocalSag sag_near(const TessellationSag& sag, const Aabb& near, double reach = 0.0);

/// The sags of the surface near the point `at`: the patches (SagPatch) whose
/// box, grown by `reach`, holds it, the index of the feature of each worst one
/// (-1: no patch is that near). Where a pair's depth was found (the centre of
/// its thickest overlap, within half the depth of both surfaces) these are the
/// facets that can have made it (docs/numerics.md, "The band at the contact").
LocalSag sag_at(const TessellationSag& sag, const Vec3& at, double reach);

/// The measurement of a file placed by an affine map (file → scene units):
/// feature boxes mapped (the box of their mapped corners), lengths (sags,
/// radii, resolution) multiplied by `stretch`, the map's largest stretch: an
/// upper bound under a non-uniform scale.
TessellationSag placed_sag(const TessellationSag& sag, const Mat4& placement, double stretch);

}  // namespace pd
