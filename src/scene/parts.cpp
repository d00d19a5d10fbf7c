#include "scene/parts.h"

#include <Eigen/SVD>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <fstream>
#include <map>
#include <mutex>
#include <new>
#include <optional>
#include <sstream>

#include "file_hash.h"
#include "geometry/convexity.h"
#include "geometry/coordinate_resolution.h"
#include "geometry/solid_distance.h"
#include "hash.h"
#include "parallel_for.h"
#include "scene/convexity_cache.h"
#include "scene/hull_cache.h"
#include "scene/mesh_loader.h"
#include "scene/setup_warnings.h"
#include "scene/split_nodes.h"
#include "scene/units.h"
#include "tolerances.h"

namespace pd {

Points apply_placement(const Points& p, const Mat4& placement) {
  return (placement.topLeftCorner<3, 3>() * p).colwise() + Vec3(placement.topRightCorner<3, 1>());
}

long Part::hull_vertex_count() const {
  long n = 0;
  for (const auto& h : pieces) n += h.vertices.cols();
  return n;
}

namespace {

// File coordinates to scene units: the unit conversion, then the transform.
Mat4 placement(const PartSpec& spec) {
  Mat4 m = spec.transform;
  m.topLeftCorner<3, 3>() *= spec.to_scene_units;
  return m;
}

// The placement's stretch factors, largest first.
Vec3 stretches(const Mat4& placement) {
  return Eigen::JacobiSVD<Eigen::Matrix3d>(placement.topLeftCorner<3, 3>()).singularValues();
}

// The largest factor by which the placement stretches a length.
double stretch(const Mat4& placement) {
  return stretches(placement)(0);
}

// A B-rep part's linear deflection in its file's units (0 for a mesh file):
// the scene's length over the placement's largest stretch.
double file_deflection(const SceneSpec& scene, const PartSpec& spec) {
  if (!spec.mesh || !is_brep_path(*spec.mesh)) return 0.0;
  return brep_deflection(scene, spec) / stretch(placement(spec));
}

std::string instance_key(const PartSpec& s, double deflection) {
  std::ostringstream k;
  k.precision(17);
  k << *s.mesh << '|' << s.to_scene_units << '|' << int(s.pieces) << '|' << deflection;
  for (int i = 0; i < 16; ++i) k << '|' << s.transform(i / 4, i % 4);
  if (s.node) k << '\0' << *s.node;  // '\0': no path or name holds it
  return k.str();
}

// The geometry a MeshFile holds: a file, or one node's meshes in it (a B-rep
// file's at one deflection).
std::string file_key(const PartSpec& s, double deflection) {
  std::ostringstream k;
  k.precision(17);
  k << *s.mesh << '|' << int(s.pieces) << '|' << deflection;
  return k.str() + (s.node ? '\0' + *s.node : "");
}

std::string load_error(const PartSpec& spec, const std::exception& e) {
  if (dynamic_cast<const MeshError*>(&e)) return e.what();  // names the file already
  return (spec.mesh ? "mesh file " + *spec.mesh + ": " : std::string()) +
         (dynamic_cast<const std::bad_alloc*>(&e) ? "out of memory while loading (corrupt file?)"
                                                  : e.what());
}

// A mesh file as its instances share it: read once (in a loader process,
// before the hulls start), each piece reduced to the vertices of its hull by
// the first instance. An affine map sends extreme points among the images of
// extreme points, so an instance hulls the placed reduced set and gets the
// hull of the placed file.
struct MeshFile {
  std::once_flag loaded;
  LoadedMeshes read;            ///< as the loader returned it; freed once reduced
  std::vector<Points> reduced;  ///< per piece, file coordinates
  std::vector<long> counts;     ///< vertices per piece as read
  HullTriangles facets;         ///< piece 0's hull facets, when hulled here (not cached)
  std::optional<std::string> error;
  std::vector<std::string> warnings;  ///< the loader's (a PLY header line skipped, …)
  bool hulls_cached = false;          ///< `reduced` and `counts` came from the hull cache
  std::string hash;                   ///< content hash, when a cache needs it
  // Pieces auto/decompose: the surface and its nonconvexity, once per file.
  std::shared_ptr<const Mesh> mesh;
  double concavity = 0.0;  ///< file units
  bool closed = false;
  double min_stretch = INFINITY, max_stretch = 0.0;  ///< over the file's instances
  int instances = 0;                                 ///< distinct placements of it
  // The only instance's placed mesh and its distances, when the convexity was
  // measured on them and the kept budget held them (PartSurface::solid).
  std::shared_ptr<const Mesh> placed;
  std::shared_ptr<const SolidDistance> solid;
  // B-rep files: the deflection asked (file units), the leaf the meshes are of
  // (-1: every leaf, joined) and the tessellation they carry.
  double deflection = 0.0;
  int leaf = -1;
  std::optional<Tessellation> tessellation;
  // Under tolerance auto: the sag (file units; from the hull cache entry when
  // it holds one), and the concavity tolerance it gives the file (scene units).
  std::optional<TessellationSag> sag;
  double concavity_tol = 0.0;
};

// A file's sag: each of its meshes measured on its own (welding across meshes
// would join unrelated instances), the features of all of them.
TessellationSag file_sag(const std::vector<Mesh>& meshes, CoordinateStorage storage) {
  TessellationSag all;
  for (const Mesh& m : meshes) {
    TessellationSag s = measure_tessellation_sag(m, storage);
    all.concave = std::max(all.concave, s.concave);
    all.convex = std::max(all.convex, s.convex);
    all.resolution = std::max(all.resolution, s.resolution);
    all.creases += s.creases;
    all.design_edges += s.design_edges;
    all.features.insert(all.features.end(), s.features.begin(), s.features.end());
  }
  return all;
}

bool keeps_surface(Pieces p) {
  return p == Pieces::kAuto || p == Pieces::kDecompose;
}

// Whether a placement stretches every length alike (units and a rotation):
// distances measured on the placed mesh are then the file's, times the stretch.
bool similarity(const Mat4& placement) {
  const Vec3 s = stretches(placement);
  return s(0) - s(2) <= tol::kSimilarPlacement * s(0);
}

// Triangles whose placed distances the parts stage may keep for the
// refinement, over the whole scene (tol::kKeptSolidTriangles).
using KeptBudget = std::atomic<long>;

// The file's nonconvexity, from the cache when it holds this file's bytes at
// this tolerance, else measured (and stored, best effort). A file with one
// instance placed without stretch is measured on its placed mesh, whose
// distances the refinement needs too: they are kept in `f` while `budget`
// lasts (which decides only what is kept, never what is measured).
StoredConvexity convexity_of(const PartSpec& spec, MeshFile& f, double concavity_tol,
                             const std::string& cache_dir, KeptBudget& budget) {
  const double tol = concavity_tol / f.max_stretch, stop_above = concavity_tol / f.min_stretch;
  const std::string key = convexity_key(f.hash, tol, stop_above);
  if (auto hit = read_cached_convexity(cache_dir, key)) return *hit;
  const Mesh& m = *f.mesh;
  ConvexityScreen c;
  const Mat4 to_scene = placement(spec);
  if (f.instances == 1 && similarity(to_scene)) {
    auto placed = std::make_shared<Mesh>();
    placed->vertices = apply_placement(m.vertices, to_scene);
    placed->triangles = m.triangles;
    const Points hull_points = apply_placement(f.reduced[0], to_scene);
    HullTriangles facets = f.facets;  // turned with the part
    for (Vec3& n : facets.normals) n = (to_scene.topLeftCorner<3, 3>() * n).normalized();
    const HullTriangles* known = facets.triangles.empty() ? nullptr : &facets;
    const long n = m.triangles.cols();
    if (budget.fetch_sub(n) >= n) {
      auto solid = std::make_shared<const SolidDistance>(*placed);
      c = screen_convexity(*placed, solid->mesh(), concavity_tol, concavity_tol, &hull_points,
                           known);
      f.placed = std::move(placed);
      f.solid = std::move(solid);
    } else {
      budget.fetch_add(n);
      c = screen_convexity(*placed, concavity_tol, concavity_tol, &hull_points, known);
    }
    c.concavity.value /= f.max_stretch;  // file units, as the cache keeps it
  } else {
    c = screen_convexity(m, tol, stop_above, &f.reduced[0],
                         f.facets.triangles.empty() ? nullptr : &f.facets);
  }
  const StoredConvexity s{c.concavity.value, c.closed};
  write_cached_convexity(cache_dir, key, s);
  return s;
}

std::string file_hash(const std::string& path, const PartsCache& cache) {
  if (cache.file_hashes) {
    const auto known = cache.file_hashes->find(path);
    if (known != cache.file_hashes->end()) return known->second;
  }
  return file_content_hash(path);
}

// The cache key of a part's geometry: its file's content hash, and for a node
// part the node path with it (a node's hulls, sag and convexity are its own);
// for a B-rep file the deflection it is meshed at too.
std::string geometry_hash(const PartSpec& spec, const PartsCache& cache, double deflection) {
  const std::string file = file_hash(*spec.mesh, cache);
  if (deflection > 0) {
    char d[32];
    std::snprintf(d, sizeof d, "%.17g", deflection);
    return Hasher().add("pdcheck-brep-v1").add(file).add(spec.node.value_or("")).add(d).hex();
  }
  if (!spec.node) return file;
  return Hasher().add("pdcheck-node-v1").add(file).add(*spec.node).hex();
}

// A node part's meshes, from its file read by node: those of its node, joined
// into one unless `split_instances`.
LoadedMeshes node_read(const LoadedMeshes& file, const std::vector<size_t>& of_node,
                       const PartSpec& spec, int& leaf) {
  LoadedMeshes out;
  out.warnings = file.warnings;
  out.error = file.error;
  if (file.error) return out;
  if (of_node.empty()) {
    out.error = "cannot load mesh file " + *spec.mesh + ": it has no node \"" + *spec.node +
                "\" (the file changed since the scene part was split?)";
    return out;
  }
  if (!file.leaf_errors.empty()) {  // a B-rep file: a node is one leaf instance
    const size_t k = of_node[0];
    leaf = int(k);
    if (!file.leaf_errors[k].empty()) out.error = file.leaf_errors[k];
    out.meshes = {file.meshes[k]};
    out.tessellations = {file.tessellations[k]};
    return out;
  }
  std::vector<Mesh> meshes;
  for (size_t k : of_node) meshes.push_back(file.meshes[k]);
  if (spec.pieces == Pieces::kMeshes || meshes.size() == 1)
    out.meshes = std::move(meshes);
  else
    out.meshes = {join_meshes(meshes)};
  return out;
}

// The file's hulls from the cache, when an earlier run (or another shard on
// this machine) stored them: true if found. The entry's sag comes with them
// when a run under tolerance auto stored one.
bool cached_hulls(const PartSpec& spec, MeshFile& f, const PartsCache& cache) {
  if (cache.dir.empty()) return false;
  f.hash = geometry_hash(spec, cache, f.deflection);
  auto hit = read_cached_hulls(cache.dir, hulls_key(f.hash, spec.pieces == Pieces::kMeshes));
  if (!hit) return false;
  f.counts = std::move(hit->counts);
  f.reduced = std::move(hit->reduced);
  f.warnings = std::move(hit->warnings);
  f.sag = std::move(hit->sag);
  f.hulls_cached = true;
  return true;
}

// Under tolerance auto, the concavity tolerance of a file: kConcavityFraction
// of the band two copies of it get at their worst features, its coordinate
// noise standing for the resolution (a float32 file far from the origin is
// not concave by its rounding). Scene units, at the file's largest stretch.
double auto_concavity_tol(const MeshFile& f, const AutoTolerance& a) {
  const double s = f.sag->concave * f.max_stretch;
  double noise = 0.0;
  for (const Points& p : f.reduced) noise = std::max(noise, coordinate_noise(p));
  noise *= f.max_stretch;
  return tol::kConcavityFraction * a.band(s, s, noise, noise);
}

void load(const PartSpec& spec, MeshFile& f, double concavity_tol, const PartsCache& cache,
          const AutoTolerance* auto_tol, KeptBudget& budget) {
  try {
    if (f.read.error) throw MeshError(*f.read.error);
    const std::vector<Mesh>& meshes = f.read.meshes;
    if (!f.read.tessellations.empty()) f.tessellation = f.read.tessellations[0];
    // Hulls first: a mesh they reject (non-finite coordinates, ...) fails as in
    // pieces "hull", before any measurement.
    bool store = false;  // the cache entry is new, or gains the sag
    if (!f.hulls_cached) {
      f.warnings = f.read.warnings;
      for (const Mesh& m : meshes) {
        f.counts.push_back(m.vertices.cols());
        f.reduced.push_back(
            convex_hull(m.vertices, f.reduced.empty() ? &f.facets : nullptr).vertices);
      }
      store = true;
    }
    if (auto_tol && !f.sag) {
      f.sag = file_sag(meshes,
                       f.tessellation ? CoordinateStorage::kDouble : CoordinateStorage::kFloat32);
      store = true;
    }
    if (store && !f.hash.empty())  // one entry per file: its hulls, and its sag under auto
      write_cached_hulls(cache.dir, hulls_key(f.hash, spec.pieces == Pieces::kMeshes),
                         {f.counts, f.reduced, f.warnings, f.sag});
    if (auto_tol) concavity_tol = auto_concavity_tol(f, *auto_tol);
    f.concavity_tol = concavity_tol;
    if (keeps_surface(spec.pieces) && meshes.size() == 1 && meshes[0].triangles.cols() > 0) {
      f.mesh = std::make_shared<const Mesh>(meshes[0]);
      if (f.hash.empty()) f.hash = geometry_hash(spec, cache, f.deflection);
      // Measured once, kept in file units; each instance scales the value by its
      // own stretch (a sole instance placed without stretch is measured on its
      // placed mesh). Voids count at the strictest instance's tolerance; the
      // estimate stops once it is nonconvex for the most lenient one.
      const StoredConvexity c = convexity_of(spec, f, concavity_tol, cache.dir, budget);
      f.concavity = c.concavity;
      f.closed = c.closed;
    }
  } catch (const std::exception& e) {
    f.reduced.clear();
    f.mesh.reset();
    f.placed.reset();
    f.solid.reset();
    f.error = load_error(spec, e);
  }
  f.read = {};
  f.facets = {};  // the screen's only
}

PartSurface surface_of(const PartSpec& spec, const MeshFile& f, bool convex) {
  PartSurface s;
  s.file_mesh = f.mesh;
  s.file_hash = f.hash;
  s.placement = placement(spec);
  s.stretch = stretch(s.placement);
  s.concavity = f.concavity * s.stretch;
  s.concavity_tol = f.concavity_tol;
  s.closed = f.closed;
  s.solid = f.solid;                                   // of the placed mesh below, when kept
  if (!convex || spec.pieces == Pieces::kDecompose) {  // only what a refinement can use
    if (f.placed) {
      s.mesh = f.placed;
    } else {
      Mesh placed;
      placed.vertices = apply_placement(f.mesh->vertices, s.placement);
      placed.triangles = f.mesh->triangles;
      s.mesh = std::make_shared<const Mesh>(std::move(placed));
    }
  }
  return s;
}

// An inline part's hull, from the cache when an earlier run (or another shard)
// hulled the same list under the same placement (large parts only).
Hull inline_hull(const PartSpec& spec, const PartsCache& cache) {
  if (cache.dir.empty() || spec.vertices->cols() < tol::kInlineHullCacheVertices)
    return convex_hull(place_points(*spec.vertices, spec));
  const std::string key =
      inline_hull_key(vertex_digest(*spec.vertices), spec.to_scene_units, spec.transform);
  if (auto hit = read_cached_hull(cache.dir, key)) return std::move(*hit);
  Hull h = convex_hull(place_points(*spec.vertices, spec));
  write_cached_hull(cache.dir, key, h);
  return h;
}

/// One part from its spec; `file` is its mesh file, shared with other instances.
Part build_part(const PartSpec& spec, MeshFile* file, double concavity_tol, const PartsCache& cache,
                const AutoTolerance* auto_tol, KeptBudget& budget) {
  Part part;
  part.id = spec.id;
  part.source = spec.mesh ? *spec.mesh : "inline";
  part.mode = spec.pieces;
  if (spec.error) {
    part.error = spec.error;
    return part;
  }
  if (file) {
    std::call_once(file->loaded, [&] {
      load(spec, *file, concavity_tol, cache, auto_tol, budget);
    });  // the first instance reduces it
    if (file->error) {
      part.error = file->error;
      return part;
    }
    part.warnings = file->warnings;
  }
  std::vector<const Points*> sets;  // the point sets to place and hull, not copied
  if (file)
    for (const Points& p : file->reduced) sets.push_back(&p);
  else
    sets.push_back(&*spec.vertices);
  try {
    for (size_t k = 0; k < sets.size(); ++k) {
      part.vertex_count += file ? file->counts[k] : sets[k]->cols();
      Hull h = file ? convex_hull(place_points(*sets[k], spec)) : inline_hull(spec, cache);
      for (auto& w : h.warnings)
        part.warnings.push_back(sets.size() > 1 ? "piece " + std::to_string(k) + ": " + w : w);
      const Aabb b = Aabb::of(h.vertices);
      part.box = k == 0 ? b : part.box.merged(b);
      part.pieces.push_back(std::move(h));
    }
    // Mesh files come as float32 (assimp's storage), inline vertices as doubles.
    double max_abs = 0.0;
    for (const Points* p : sets) max_abs = std::max(max_abs, max_abs_coordinate(*p));
    const double placed_max_abs =
        std::max(part.box.lo.cwiseAbs().maxCoeff(), part.box.hi.cwiseAbs().maxCoeff());
    // B-rep meshes are made in double precision.
    const bool float32 = file != nullptr && !file->tessellation;
    part.resolution =
        coordinate_resolution(max_abs, float32, stretch(placement(spec)), placed_max_abs);
    if (file && file->tessellation) {
      PartBrep b;
      b.file = *spec.mesh;
      b.leaf = file->leaf;
      b.placement = placement(spec);
      b.tessellation = *file->tessellation;
      const double s = stretch(b.placement);
      b.tessellation.deflection *= s;
      b.tessellation.sag *= s;
      b.tessellation.tolerance *= s;
      part.brep = std::move(b);
    }
    if (auto_tol) {
      PartSag sag;
      if (file) sag.measured = placed_sag(*file->sag, placement(spec), stretch(placement(spec)));
      sag.measured.resolution = *part.resolution;  // one owner: the part's resolution
      sag.declared = spec.sag;
      // A B-rep part's sag is known from its faces, not measured from creases.
      if (part.brep && !spec.sag) sag.declared = part.brep->tessellation.sag;
      part.sag = std::move(sag);
    }
    if (file && file->mesh) {
      part.convex = file->concavity * stretch(placement(spec)) <= file->concavity_tol;
      part.surface = surface_of(spec, *file, *part.convex);
    }
  } catch (const std::exception& e) {
    part.pieces.clear();
    part.surface.reset();
    part.error = load_error(spec, e);
  }
  return part;
}

/// The scene's distinct geometry: the same mesh file under the same units,
/// transform and pieces is hulled once, and read once under any transform.
/// Inline parts are distinct.
struct DistinctParts {
  std::vector<const PartSpec*> unique;
  std::vector<std::optional<size_t>> file_of;  ///< per distinct part: its mesh file
  size_t files = 0;                            ///< distinct mesh files
  std::vector<size_t> users;                   ///< scene parts per distinct geometry
  std::vector<size_t> source;                  ///< per scene part: its distinct part
  std::vector<double> deflection;              ///< per distinct part: file_deflection
};

DistinctParts distinct_parts(const SceneSpec& scene) {
  DistinctParts d;
  d.source.resize(scene.parts.size());
  std::map<std::string, size_t> files, seen;
  for (size_t k = 0; k < scene.parts.size(); ++k) {
    const PartSpec& spec = scene.parts[k];
    const double deflection = file_deflection(scene, spec);
    if (spec.mesh) {
      const auto [it, fresh] = seen.emplace(instance_key(spec, deflection), d.unique.size());
      d.source[k] = it->second;
      if (!fresh) {
        ++d.users[it->second];
        continue;
      }
    } else {
      d.source[k] = d.unique.size();
    }
    d.unique.push_back(&spec);
    d.users.push_back(1);
    d.file_of.emplace_back();
    d.deflection.push_back(deflection);
    if (spec.mesh && !spec.error)
      d.file_of.back() = files.emplace(file_key(spec, deflection), files.size()).first->second;
  }
  d.files = files.size();
  return d;
}

}  // namespace

std::vector<Part> build_parts(const SceneSpec& scene, int threads,
                              const std::function<void(size_t)>& on_built, double load_timeout,
                              const PartsCache& cache, double load_memory_mb,
                              const MeshLoadHook& before_load) {
  const DistinctParts distinct = distinct_parts(scene);
  const std::vector<const PartSpec*>& unique = distinct.unique;
  const std::vector<std::optional<size_t>>& file_of = distinct.file_of;
  const std::vector<size_t>& users = distinct.users;
  const std::vector<size_t>& source = distinct.source;

  // Hulls are independent: qhull_r keeps its state per run, each assimp
  // Importer its own, and build_part catches whatever it throws. The first
  // instance of a mesh file reduces it; others of the same file wait for it.
  const double concavity_tol = tol::kConcavityFraction * scene.tolerance.value_or(0.0);
  const AutoTolerance* auto_tol = scene.auto_tolerance ? &*scene.auto_tolerance : nullptr;
  std::vector<Part> built(unique.size());
  std::vector<MeshFile> mesh_files(distinct.files);
  // Every mesh file is read first, in loader processes: forked here, while
  // this process has one thread (see mesh_loader_processes.cpp).
  // A file whose hulls are cached is read only when its surface is kept.
  // A split file is read once, by node, for all its node parts.
  std::vector<MeshRequest> requests;
  std::vector<std::vector<size_t>> requested;  // per request: its files
  std::vector<const PartSpec*> file_spec(distinct.files);
  std::map<std::string, size_t> by_node;  // a split file's path -> its request
  for (size_t u = 0; u < unique.size(); ++u) {
    if (!file_of[u] || file_spec[*file_of[u]]) continue;
    const size_t f = *file_of[u];
    file_spec[f] = unique[u];
    const double deflection = distinct.deflection[u];
    mesh_files[f].deflection = deflection;
    // A B-rep file is always read: its tessellation is in no cache.
    if (cached_hulls(*unique[u], mesh_files[f], cache) && !keeps_surface(unique[u]->pieces) &&
        (!auto_tol || mesh_files[f].sag) && deflection == 0)
      continue;
    if (unique[u]->node) {
      std::ostringstream key;  // a split file, read once per deflection for all its node parts
      key.precision(17);
      key << deflection << '|' << *unique[u]->mesh;
      const auto [it, fresh] = by_node.emplace(key.str(), requests.size());
      if (fresh) {
        requests.push_back({*unique[u]->mesh, true, true, false, deflection});
        requested.emplace_back();
      }
      requested[it->second].push_back(f);
      continue;
    }
    requests.push_back(
        {*unique[u]->mesh, unique[u]->pieces == Pieces::kMeshes, false, false, deflection});
    requested.push_back({f});
  }
  for (size_t u = 0; u < unique.size(); ++u)
    if (file_of[u]) {
      MeshFile& f = mesh_files[*file_of[u]];
      const double s = stretch(placement(*unique[u]));
      f.min_stretch = std::min(f.min_stretch, s);
      f.max_stretch = std::max(f.max_stretch, s);
      ++f.instances;
    }
  if (!requests.empty()) {
    std::vector<LoadedMeshes> read =
        load_meshes_isolated(requests, threads, load_timeout, load_memory_mb, before_load);
    for (size_t r = 0; r < read.size(); ++r) {
      if (!requests[r].by_node) {
        mesh_files[requested[r][0]].read = std::move(read[r]);
        continue;
      }
      std::map<std::string, std::vector<size_t>> meshes_of_node;
      for (size_t m = 0; m < read[r].nodes.size(); ++m)
        meshes_of_node[read[r].nodes[m]].push_back(m);
      for (size_t f : requested[r]) {
        const auto it = meshes_of_node.find(*file_spec[f]->node);
        mesh_files[f].read =
            node_read(read[r], it == meshes_of_node.end() ? std::vector<size_t>{} : it->second,
                      *file_spec[f], mesh_files[f].leaf);
      }
      read[r] = {};
    }
  }
  KeptBudget budget{tol::kKeptSolidTriangles};
  parallel_for(unique.size(), threads, [&](size_t u) {
    built[u] = build_part(*unique[u], file_of[u] ? &mesh_files[*file_of[u]] : nullptr,
                          concavity_tol, cache, auto_tol, budget);
    if (on_built) on_built(users[u]);
  });

  std::vector<Part> parts;
  parts.reserve(scene.parts.size());
  const std::string units = scene.units.value_or("mm");
  for (size_t k = 0; k < scene.parts.size(); ++k) {
    Part p = built[source[k]];
    p.id = scene.parts[k].id;
    p.motion = scene.parts[k].motion;
    if (!p.error) {
      if (auto w = non_rigid_placement(scene.parts[k].transform)) p.warnings.push_back(*w);
      const PartSpec& spec = scene.parts[k];
      if (spec.units_key && spec.mesh && format_unit(*spec.mesh) == "mm" &&
          is_brep_path(*spec.mesh) && *spec.units_key != "mm")
        p.warnings.push_back(spec.where + ": units \"" + *spec.units_key +
                             "\" does not apply: a STEP file declares its own unit, and is read "
                             "in mm (converted to the scene's)");
      if (p.resolution && scene.tolerance)
        if (auto w = resolution_warning(*scene.tolerance, *p.resolution, units))
          p.warnings.push_back(*w);
    }
    parts.push_back(std::move(p));
  }
  return parts;
}

std::vector<Part> load_scene_parts(const std::string& path, const std::optional<std::string>& units,
                                   std::optional<double> tolerance, int threads,
                                   double load_timeout) {
  SceneSpec scene = load_scene_file(path, units, threads);
  split_node_parts(scene, {threads, load_timeout, kAutoLoadMemory, {}, ""});
  if (tolerance) scene.tolerance = *tolerance;
  return build_parts(scene, threads, {}, load_timeout);
}

}  // namespace pd
