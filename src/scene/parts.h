// Parts: a scene's part specs turned into convex pieces in scene units.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/aabb.h"
#include "geometry/hull.h"
#include "geometry/mesh.h"
#include "geometry/motion.h"
#include "geometry/tessellation_sag.h"
#include "scene/mesh_loader.h"
#include "scene/mesh_store.h"
#include "scene/scene.h"

namespace pd {

/// A mesh part's surface, for the nonconvex refinement (pieces auto and
/// decompose): the file's mesh in its own coordinates (shared by its
/// instances; in the mesh store, read back where a stage needs it), where it
/// is placed, and its nonconvexity measured once per file.
struct PartSurface {
  std::optional<StoredMesh> stored;       ///< file coordinates, in the mesh store
  std::shared_ptr<const Mesh> file_mesh;  ///< or held here (file coordinates)
  std::string file_hash;                  ///< content hash of the mesh file (cache key)
  Mat4 placement = Mat4::Identity();      ///< file → scene units (units, then transform)
  double stretch = 1.0;                   ///< the placement's largest stretch factor
  double concavity = 0.0;      ///< the file's measured nonconvexity, scene units; NaN: not yet
  double concavity_tol = 0.0;  ///< what it is measured against (scene units; per file under auto)
  bool closed = false;         ///< the file's mesh bounds a solid (once measured)
  double noise = 0.0;          ///< the file's coordinate noise (file units)
};

/// The surface's mesh in file coordinates: the one held, or read back from the
/// store. Throws std::runtime_error when the store has lost it.
std::shared_ptr<const Mesh> file_mesh_of(const PartSurface& s);

/// The surface's mesh placed (scene units), as file_mesh_of reads it.
Mesh placed_mesh_of(const PartSurface& s);

/// File points in scene units under a surface's placement: the one
/// arithmetic every placed surface uses (the parts stage's and the
/// refinement's), so they agree to the bit.
Points apply_placement(const Points& p, const Mat4& placement);

/// A part's convex decomposition, once the batch stage has made one (placed).
struct PartDecomposition {
  std::vector<Hull> pieces;
  double seconds = 0.0;  ///< computing it (as first computed, when cached)
  bool cached = false;   ///< read from the decomposition cache
  bool complete = true;  ///< false: time box or failure; the pieces are a fallback
  std::string note;
};

/// A part's tessellation sag, measured under `tolerance: auto` (docs/numerics.md).
struct PartSag {
  TessellationSag measured;  ///< placed: scene units (an inline part: its resolution only)
  std::optional<double>
      declared;  ///< the part's `sag` (scene units): replaces the measured concave sag
};

/// A B-rep part (STEP, .brep): where its exact solids are, how they were
/// meshed and the error that mesh carries.
struct PartBrep {
  std::string file;                   ///< the B-rep file
  int leaf = -1;                      ///< its leaf instance in the file (BrepFile::leaves); -1: all
  Mat4 placement = Mat4::Identity();  ///< file units → scene units (units, then transform)
  double stretch = 1.0;               ///< the placement's largest stretch of lengths
  Tessellation tessellation;          ///< in scene units (deflection, sag)
};

struct Part {
  std::string id;
  std::string source;  ///< the mesh path, or "inline"
  long vertex_count = 0;
  std::vector<Hull> pieces;  ///< convex pieces (one unless pieces = "meshes")
  Aabb box;
  std::vector<std::string> warnings;
  std::optional<std::string> error;   ///< the part could not be used: its pairs are errors
  std::optional<RigidMotion> motion;  ///< moving parts only (checks.motion)
  Pieces mode = Pieces::kHull;
  /// Measured for decompose and B-rep parts; for pieces auto mesh parts when a
  /// pair needs it (scene/part_convexity.h), else unset.
  std::optional<bool> convex;
  std::optional<PartSurface> surface;              ///< pieces auto/decompose mesh parts
  std::optional<PartDecomposition> decomposition;  ///< set by the batch stage when used
  /// Scene units: the spacing of its stored coordinates at their magnitude
  /// (float32 for mesh files, as assimp stores them; double inline), carried by
  /// its placement (geometry/coordinate_resolution.h). Set for usable parts.
  std::optional<double> resolution;
  std::optional<PartSag> sag;    ///< under tolerance auto
  std::optional<PartBrep> brep;  ///< B-rep parts

  /// Whether a pair flagged by the hull stage must look past this part's hull.
  bool refinable() const { return refinable_as(convex); }
  /// The same, were its convexity `c`.
  bool refinable_as(std::optional<bool> c) const {
    return surface && (mode == Pieces::kDecompose || (mode == Pieces::kAuto && c == false));
  }

  /// A pieces auto mesh part: its convexity is measured only where a pair's
  /// verdict turns on it (batch/convexity_on_demand.h), so `convex` may stay unset.
  bool convexity_on_demand() const { return surface && mode == Pieces::kAuto; }

  long hull_vertex_count() const;
};

/// Where build_parts caches measured convexities, and the mesh files' content
/// hashes when the caller has them (else each file is hashed there).
struct PartsCache {
  std::string dir;                                                  ///< "" = no cache
  const std::map<std::string, std::string>* file_hashes = nullptr;  ///< path -> content hash
};

/// Loads, transforms and hulls every part. A part that fails gets `error` set
/// and the rest go on. A mesh file is read once (and reduced to its hull's
/// vertices once) whatever its instances' transforms; the same file under the
/// same units, transform and pieces is hulled once. `threads` > 1 hulls distinct parts in
/// parallel (the result does not depend on it); every thread has ended on return.
/// `on_built(n)`, when given, is called (from any thread) as the geometry
/// of n scene parts is ready (a file's parts as its loader hands it back), for
/// progress. Mesh files are read first, in up to
/// `threads` loader processes, each file within `load_timeout` seconds (0 = no
/// limit) and `load_memory_mb` (load_meshes_isolated): a reader that hangs,
/// crashes or allocates without end costs only its file's parts. Forks: call
/// it from a process with one thread.
/// `cache`: where measured convexities are cached (PartsCache); the surfaces
/// that pieces auto and decompose keep go to its mesh store (scene/mesh_store.h),
/// or without a cache directory to a temporary one that the parts share. Under
/// `scene.auto_tolerance` every part's sag is measured (once per file, cached
/// beside the hulls) and a file's concavity tolerance is kConcavityFraction of
/// the band two copies of it would get. `before_load`:
/// fault injection for tests (mesh_loader.h).
std::vector<Part> build_parts(const SceneSpec& scene, int threads = 1,
                              const std::function<void(size_t)>& on_built = {},
                              double load_timeout = kDefaultLoadTimeout,
                              const PartsCache& cache = {}, double load_memory_mb = kAutoLoadMemory,
                              const MeshLoadHook& before_load = {});

/// The parts of the scene file at `path` as build_parts makes them (no cache),
/// read in `units` when given and with `tolerance` in place of the file's when
/// given: the geometry of a saved report (report/html_from_report.h). Throws
/// SceneError when the scene cannot be read.
std::vector<Part> load_scene_parts(const std::string& path, const std::optional<std::string>& units,
                                   std::optional<double> tolerance, int threads,
                                   double load_timeout);

}  // namespace pd
