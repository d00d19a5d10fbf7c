#include "scene/parts.h"

#include <malloc.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <new>
#include <optional>
#include <sstream>
#include <type_traits>

#include "file_hash.h"
#include "geometry/convexity.h"
#include "geometry/coordinate_resolution.h"
#include "geometry/same_position.h"
#include "hash.h"
#include "parallel_for.h"
#include "scene/convexity_cache.h"
#include "scene/hull_cache.h"
#include "scene/mesh_loader.h"
#include "scene/placement.h"
#include "scene/setup_warnings.h"
#include "scene/split_nodes.h"
#include "scene/units.h"
#include "tolerances.h"

namespace pd {

Points apply_placement(const Points& p, const Mat4& placement) {
  return (placement.topLeftCorner<3, 3>() * p).colwise() + Vec3(placement.topRightCorner<3, 1>());
}

std::shared_ptr<const Mesh> file_mesh_of(const PartSurface& s) {
  if (s.file_mesh) return s.file_mesh;
  if (!s.stored || !s.stored->store) throw std::runtime_error("the part keeps no surface");
  std::optional<Mesh> m = s.stored->store->get(s.stored->key);
  if (!m)
    throw std::runtime_error("its surface is gone from the mesh store " + s.stored->store->dir() +
                             " (removed or damaged while the run went on)");
  return std::make_shared<const Mesh>(std::move(*m));
}

Mesh placed_mesh_of(const PartSurface& s) {
  const std::shared_ptr<const Mesh> m = file_mesh_of(s);
  return {apply_placement(m->vertices, s.placement), m->triangles};
}

long Part::hull_vertex_count() const {
  long n = 0;
  for (const auto& h : pieces) n += h.vertices.cols();
  return n;
}

namespace {

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

// The caches, and the mesh store where the surfaces kept go.
struct PartsStorage : PartsCache {
  std::shared_ptr<const MeshStore> meshes;
};

// A mesh file as its instances share it: read once, in a loader process that
// reduces each piece to the vertices of its hull, measures what the parts
// stage needs and stores the surface (digest); the meshes themselves never
// reach this process. An affine map sends extreme points among the images of
// extreme points, so an instance hulls the placed reduced set and gets the
// hull of the placed file.
struct MeshFile {
  LoadedMeshes read;            ///< as the loader returned it; freed once reduced
  std::vector<Points> reduced;  ///< per piece, file coordinates
  std::vector<long> counts;     ///< vertices per piece as read
  HullTriangles facets;         ///< piece 0's hull facets, when hulled here (not cached)
  std::optional<std::string> error;
  std::vector<std::string> warnings;  ///< the loader's (a PLY header line skipped, …)
  bool hulls_cached = false;          ///< `reduced` and `counts` came from the hull cache
  std::string hash;                   ///< content hash, when a cache needs it
  // Pieces auto/decompose: the surface (in the mesh store) and its
  // nonconvexity, once per file.
  std::optional<StoredMesh> stored;
  double concavity = 0.0;  ///< file units
  /// File units: the rounding noise of its stored coordinates (coordinate_noise).
  /// A concavity within it is the rounding of a convex part (a float32 sphere
  /// far from the origin), which a hull solves exactly: such a part is convex.
  double noise = 0.0;
  bool closed = false;
  double min_stretch = INFINITY, max_stretch = 0.0;  ///< over the file's instances
  int instances = 0;                                 ///< distinct placements of it
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

// A pieces auto mesh part's convexity decides only pairs whose hulls
// interfere, and only when the other part is convex too: the batch stage
// measures it when such a pair needs it (scene/part_convexity.h), B-rep parts
// as well; decompose parts keep measuring here. The loader's side of
// Part::convexity_on_demand.
bool convexity_left_for_pairs(const PartSpec& spec) {
  return spec.pieces == Pieces::kAuto;
}

// Whether a placement stretches every length alike (units and a rotation):
// distances measured on the placed mesh are then the file's, times the stretch.
bool similarity(const Mat4& placement) {
  const Vec3 s = stretches(placement);
  return s(0) - s(2) <= tol::kSimilarPlacement * s(0);
}

// The file's nonconvexity, from the cache when it holds this file's bytes at
// this tolerance, else measured (and stored, best effort). A file with one
// instance placed without stretch is measured on its placed mesh, as the
// refinement sees it.
StoredConvexity convexity_of(const PartSpec& spec, MeshFile& f, const Mesh& m, double concavity_tol,
                             const std::string& cache_dir) {
  // Measured until nonconvex for the most lenient instance, whose bar is its
  // concavity tolerance or the coordinates' noise, whichever is larger.
  const double tol = concavity_tol / f.max_stretch,
               stop_above = std::max(concavity_tol / f.min_stretch, f.noise);
  const std::string key = convexity_key(f.hash, tol, stop_above);
  if (auto hit = read_cached_convexity(cache_dir, key)) return *hit;
  ConvexityScreen c;
  const Mat4 to_scene = placement(spec);
  if (f.instances == 1 && similarity(to_scene)) {
    Mesh placed;
    placed.vertices = apply_placement(m.vertices, to_scene);
    placed.triangles = m.triangles;
    const Points hull_points = apply_placement(f.reduced[0], to_scene);
    HullTriangles facets = f.facets;  // turned with the part
    for (Vec3& n : facets.normals) n = (to_scene.topLeftCorner<3, 3>() * n).normalized();
    const HullTriangles* known = facets.triangles.empty() ? nullptr : &facets;
    const double placed_stop = std::max(concavity_tol, f.noise * f.max_stretch);
    c = screen_convexity(placed, concavity_tol, placed_stop, &hull_points, known);
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
// for a B-rep file the deflection it is meshed at too, and the version of the
// sag bound its entries hold (raised whenever the bound changes).
std::string geometry_hash(const PartSpec& spec, const PartsCache& cache, double deflection) {
  const std::string file = file_hash(*spec.mesh, cache);
  if (deflection > 0) {
    char d[32];
    std::snprintf(d, sizeof d, "%.17g", deflection);
    return Hasher().add(brep_mesh_version()).add(file).add(spec.node.value_or("")).add(d).hex();
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
    if (k < file.triangle_sags.size()) out.triangle_sags = {file.triangle_sags[k]};
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
  const double noise = f.noise * f.max_stretch;
  return tol::kConcavityFraction * a.band(s, s, noise, noise);
}

// What the file's hulls (cached or just made) settle: the noise of its
// coordinates and, under auto, its concavity tolerance.
void settle_hulls(MeshFile& f, double concavity_tol, const AutoTolerance* auto_tol) {
  f.noise = 0.0;  // the hull's points hold the largest coordinate and span the box
  for (const Points& p : f.reduced) f.noise = std::max(f.noise, coordinate_noise(p));
  if (auto_tol) concavity_tol = auto_concavity_tol(f, *auto_tol);
  f.concavity_tol = concavity_tol;
}

// Runs in a loader process, on a file it has just read: the file's hulls, its
// sag under auto and, for pieces auto/decompose, its nonconvexity, with the
// surface put in the store for the stages that need triangles again. What
// was read is let go: the parent gets only what digest_bytes holds.
void digest(const PartSpec& spec, MeshFile& f, double concavity_tol, const PartsStorage& cache,
            const AutoTolerance* auto_tol) {
  try {
    if (f.read.error) throw MeshError(*f.read.error);
    const std::vector<Mesh>& meshes = f.read.meshes;
    if (!f.read.tessellations.empty()) f.tessellation = f.read.tessellations[0];
    // Hulls first: a mesh they reject (non-finite coordinates, ...) fails as in
    // pieces "hull", before any measurement.
    bool store = false;          // the cache entry is new, or gains the sag
    std::vector<int> sole_weld;  // a sole mesh's, when its hulls were made here: the store's
    if (!f.hulls_cached) {
      f.warnings = f.read.warnings;
      long open = 0;
      for (const Mesh& m : meshes) {
        f.counts.push_back(m.vertices.cols());
        // Welded once for all: qhull on each position once (an STL file
        // repeats every corner about six times), the open-shell check, and
        // the store's copy below.
        std::vector<int> first = first_at_same_position(m.vertices);
        f.reduced.push_back(convex_hull(distinct_positions(m.vertices, first),
                                        f.reduced.empty() ? &f.facets : nullptr)
                                .vertices);
        open += boundary_edges(m, first);
        if (meshes.size() == 1) sole_weld = std::move(first);
      }
      if (open > 0) f.warnings.push_back(open_mesh_warning(open));  // cached with the hulls
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
    settle_hulls(f, concavity_tol, auto_tol);
    if (keeps_surface(spec.pieces) && meshes.size() == 1 && meshes[0].triangles.cols() > 0) {
      if (f.hash.empty()) f.hash = geometry_hash(spec, cache, f.deflection);
      // Measured once, kept in file units; each instance scales the value by its
      // own stretch (a sole instance placed without stretch is measured on its
      // placed mesh). Voids count at the strictest instance's tolerance; the
      // estimate stops once it is nonconvex for the most lenient one.
      if (convexity_left_for_pairs(spec)) {
        f.concavity = std::numeric_limits<double>::quiet_NaN();  // unmeasured
      } else {
        const StoredConvexity c = convexity_of(spec, f, meshes[0], f.concavity_tol, cache.dir);
        f.concavity = c.concavity;
        f.closed = c.closed;
      }
      std::string why =
          cache.meshes->put(f.hash, meshes[0], sole_weld.empty() ? nullptr : &sole_weld);
      // Its hull and facets too, for the convexity measure a pair may ask for.
      if (why.empty() && convexity_left_for_pairs(spec) && !f.hulls_cached)
        why = cache.meshes->put_hull(f.hash, f.reduced[0], f.facets);
      // A B-rep surface's triangles carry their faces' sags (where on the part
      // its sag is): kept beside it for the exact stage.
      if (why.empty() && !f.read.triangle_sags.empty() &&
          long(f.read.triangle_sags[0].size()) == meshes[0].triangles.cols())
        why = cache.meshes->put_sags(f.hash, f.read.triangle_sags[0]);
      if (!why.empty())
        throw std::runtime_error("its surface cannot be kept for the refinement: " + why);
      f.stored = StoredMesh{nullptr, f.hash};
    }
  } catch (const std::exception& e) {
    f.reduced.clear();
    f.stored.reset();
    f.error = load_error(spec, e);
  }
  f.read = {};
  f.facets = {};  // the screen's only
}

// What a loader hands back of a digested file: 'E' and the error, or 'F' and
// its fields as written below (this machine's byte order: the reader is a
// fork of the writer).
class DigestWriter {
 public:
  template <class T>
  DigestWriter& put(const T& x) {
    static_assert(std::is_trivially_copyable_v<T>);
    out_.append(reinterpret_cast<const char*>(&x), sizeof x);
    return *this;
  }
  DigestWriter& put(const std::string& s) {
    put(std::uint64_t(s.size()));
    out_ += s;
    return *this;
  }
  std::string bytes() && { return std::move(out_); }

 private:
  std::string out_ = "F";
};

class DigestReader {
 public:
  explicit DigestReader(const std::string& s) : s_(s) {}
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    T x;
    take(&x, sizeof x);
    return x;
  }
  std::string string() {
    const auto n = get<std::uint64_t>();
    if (n > s_.size() - at_) throw std::runtime_error("malformed answer from the loader process");
    std::string out = s_.substr(at_, n);
    at_ += n;
    return out;
  }

 private:
  void take(void* to, size_t n) {
    if (s_.size() - at_ < n) throw std::runtime_error("short answer from the loader process");
    std::memcpy(to, s_.data() + at_, n);
    at_ += n;
  }
  const std::string& s_;
  size_t at_ = 1;
};

std::string digest_bytes(const MeshFile& f) {
  if (f.error) return "E" + *f.error;
  DigestWriter w;
  w.put(stored_hulls_bytes({f.counts, f.reduced, f.warnings, f.sag}));
  w.put(f.hash).put(f.noise).put(f.concavity_tol).put(f.concavity).put(std::uint8_t(f.closed));
  w.put(std::int32_t(f.leaf)).put(std::uint8_t(bool(f.tessellation)));
  if (f.tessellation) w.put(*f.tessellation);
  w.put(std::uint8_t(bool(f.stored)));
  if (f.stored) w.put(f.stored->key);
  return std::move(w).bytes();
}

// In the parent: a loader's digest of `f` into it.
void take_digest(const std::string& bytes, MeshFile& f,
                 const std::shared_ptr<const MeshStore>& store) {
  if (bytes.empty()) throw std::runtime_error("empty answer from the loader process");
  if (bytes[0] == 'E') {
    f.error = bytes.substr(1);
    return;
  }
  DigestReader r(bytes);
  auto hulls = stored_hulls_from_bytes(r.string());
  if (!hulls) throw std::runtime_error("malformed answer from the loader process");
  f.counts = std::move(hulls->counts);
  f.reduced = std::move(hulls->reduced);
  f.warnings = std::move(hulls->warnings);
  f.sag = std::move(hulls->sag);
  f.hash = r.string();
  f.noise = r.get<double>();
  f.concavity_tol = r.get<double>();
  f.concavity = r.get<double>();
  f.closed = r.get<std::uint8_t>() != 0;
  f.leaf = r.get<std::int32_t>();
  if (r.get<std::uint8_t>()) f.tessellation = r.get<Tessellation>();
  if (r.get<std::uint8_t>()) {
    StoredMesh m;
    m.store = store;
    m.key = r.string();
    f.stored = std::move(m);
  }
}

// A file whose hulls are cached needs no read when its surface is not kept,
// or is in the store with its nonconvexity cached: then it is settled here.
bool settled_from_cache(const PartSpec& spec, MeshFile& f, double concavity_tol,
                        const PartsStorage& cache, const AutoTolerance* auto_tol) {
  if (!f.hulls_cached || (auto_tol && !f.sag) || f.deflection != 0) return false;
  settle_hulls(f, concavity_tol, auto_tol);
  if (!keeps_surface(spec.pieces)) return true;
  if (f.counts.size() != 1 || !cache.meshes || !cache.meshes->has(f.hash)) return false;
  if (convexity_left_for_pairs(spec)) {
    f.concavity = std::numeric_limits<double>::quiet_NaN();
    f.stored = StoredMesh{cache.meshes, f.hash};
    return true;
  }
  const double tol = f.concavity_tol / f.max_stretch,
               stop_above = std::max(f.concavity_tol / f.min_stretch, f.noise);
  const auto c = read_cached_convexity(cache.dir, convexity_key(f.hash, tol, stop_above));
  if (!c) return false;
  f.concavity = c->concavity;
  f.closed = c->closed;
  f.stored = StoredMesh{cache.meshes, f.hash};
  return true;
}

PartSurface surface_of(const PartSpec& spec, const MeshFile& f) {
  PartSurface s;
  s.stored = f.stored;
  s.file_hash = f.hash;
  s.placement = placement(spec);
  s.stretch = stretch(s.placement);
  s.concavity = f.concavity * s.stretch;
  s.concavity_tol = f.concavity_tol;
  s.closed = f.closed;
  s.noise = f.noise;
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
Part build_part(const PartSpec& spec, const MeshFile* file, const PartsCache& cache,
                const AutoTolerance* auto_tol) {
  Part part;
  part.id = spec.id;
  part.source = spec.mesh ? *spec.mesh : "inline";
  part.mode = spec.pieces;
  if (spec.error) {
    part.error = spec.error;
    return part;
  }
  if (file) {
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
      // The file's reduced points are its hull's vertices: placed, they are the
      // placed hull's.
      Hull h =
          file ? hull_of_hull_vertices(place_points(*sets[k], spec)) : inline_hull(spec, cache);
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
      b.stretch = s;
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
    if (file && file->stored) {
      // Convex within the concavity tolerance, or within the rounding of the
      // coordinates as stored (docs/numerics.md, kConcavityFraction).
      const double k = stretch(placement(spec));
      if (!std::isnan(file->concavity))  // else measured where a pair needs it
        part.convex = file->concavity * k <= std::max(file->concavity_tol, file->noise * k);
      part.surface = surface_of(spec, *file);
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

  // Every mesh file is read, reduced and measured in loader processes, forked
  // here while this process has one thread (see mesh_loader_processes.cpp);
  // each instance then hulls its placed reduced points on a thread pool.
  const double concavity_tol = tol::kConcavityFraction * scene.tolerance.value_or(0.0);
  const AutoTolerance* auto_tol = scene.auto_tolerance ? &*scene.auto_tolerance : nullptr;
  std::vector<Part> built(unique.size());
  std::vector<MeshFile> mesh_files(distinct.files);
  PartsStorage with_store;  // surfaces kept go to the mesh store
  static_cast<PartsCache&>(with_store) = cache;
  if (!with_store.meshes)
    for (size_t u = 0; u < unique.size() && !with_store.meshes; ++u)
      if (file_of[u] && keeps_surface(unique[u]->pieces))
        with_store.meshes =
            cache.dir.empty() ? MeshStore::temporary() : MeshStore::in_cache(cache.dir);
  std::vector<const PartSpec*> file_spec(distinct.files);
  // Progress counts scene parts as their file is digested (most of the
  // stage), inline parts as they are hulled.
  std::vector<size_t> file_users(distinct.files, 0);
  const auto done_file = [&](size_t f) {
    if (on_built && file_users[f] > 0) on_built(file_users[f]);
  };
  for (size_t u = 0; u < unique.size(); ++u)
    if (file_of[u]) {
      file_users[*file_of[u]] += users[u];
      MeshFile& f = mesh_files[*file_of[u]];
      const double s = stretch(placement(*unique[u]));
      f.min_stretch = std::min(f.min_stretch, s);
      f.max_stretch = std::max(f.max_stretch, s);
      ++f.instances;
      if (!file_spec[*file_of[u]]) {
        file_spec[*file_of[u]] = unique[u];
        f.deflection = distinct.deflection[u];
      }
    }
  // A file settled from the cache is not read. A split file is read once, by
  // node, for all its node parts.
  std::vector<MeshRequest> requests;
  std::vector<std::vector<size_t>> requested;  // per request: its files
  std::map<std::string, size_t> by_node;       // a split file's path -> its request
  // Per B-rep read the split kept: each node's mesh (a node is one leaf).
  std::map<const LoadedMeshes*, std::map<std::string, int>> mesh_of_node;
  for (size_t f = 0; f < distinct.files; ++f) {
    const PartSpec& spec = *file_spec[f];
    const double deflection = mesh_files[f].deflection;
    // A B-rep file's read goes to the cache, unless split_node_parts has it.
    const auto brep_read_cache = [&](MeshRequest& r) {
      if (deflection == 0 || r.read || cache.dir.empty()) return;
      r.read_cache_dir = cache.dir;
      r.read_cache_key = brep_read_cache_key(r.path, file_hash(r.path, cache), deflection);
    };
    // A B-rep file split_node_parts read whole at this deflection is not read again.
    const auto read_already = [&](const PartSpec& p) -> const LoadedMeshes* {
      if (!scene.brep_reads || deflection == 0) return nullptr;
      const auto it = scene.brep_reads->find(brep_read_key(*p.mesh, deflection));
      return it == scene.brep_reads->end() ? nullptr : &it->second;
    };
    // A B-rep file is always read, for its tessellation: from the cache
    // entry of its read when there is one (MeshRequest::read_cache_key).
    if (cached_hulls(spec, mesh_files[f], with_store) &&
        settled_from_cache(spec, mesh_files[f], concavity_tol, with_store, auto_tol)) {
      done_file(f);
      continue;
    }
    if (spec.node && !read_already(spec)) {
      std::ostringstream key;  // a split file, read once per deflection for all its node parts
      key.precision(17);
      key << deflection << '|' << *spec.mesh;
      const auto [it, fresh] = by_node.emplace(key.str(), requests.size());
      if (fresh) {
        requests.push_back({*spec.mesh, true, true, false, deflection, INFINITY, nullptr});
        requested.emplace_back();
        brep_read_cache(requests.back());
      }
      requested[it->second].push_back(f);
      continue;
    }
    // A file or, where the split read it already, one node of it: the loaders
    // digest a STEP assembly's leaves side by side.
    requests.push_back({*spec.mesh, spec.pieces == Pieces::kMeshes, bool(spec.node), false,
                        deflection, INFINITY, read_already(spec)});
    if (spec.node) {
      const LoadedMeshes& read = *requests.back().read;
      auto [index, fresh] = mesh_of_node.emplace(&read, std::map<std::string, int>{});
      if (fresh)
        for (size_t m = 0; m < read.nodes.size(); ++m) index->second.emplace(read.nodes[m], int(m));
      const auto it = index->second.find(*spec.node);
      requests.back().node_mesh = it == index->second.end() ? -2 : it->second;
    }
    requested.push_back({f});
    brep_read_cache(requests.back());
  }
  if (!requests.empty()) {
    // In the loader: each file of the request digested, its bytes one after another.
    auto digest_request = [&](size_t r, LoadedMeshes&& read) {
      std::map<std::string, std::vector<size_t>> meshes_of_node;
      if (requests[r].by_node)
        for (size_t m = 0; m < read.nodes.size(); ++m) meshes_of_node[read.nodes[m]].push_back(m);
      std::string out;
      for (size_t f : requested[r]) {
        MeshFile& file = mesh_files[f];
        if (requests[r].by_node) {
          const auto it = meshes_of_node.find(*file_spec[f]->node);
          file.read =
              node_read(read, it == meshes_of_node.end() ? std::vector<size_t>{} : it->second,
                        *file_spec[f], file.leaf);
          // One node taken from the split's read: its leaf is its place there.
          if (requests[r].node_mesh >= 0 && !file.read.error) file.leaf = requests[r].node_mesh;
        } else {
          file.read = std::move(read);
        }
        digest(*file_spec[f], file, concavity_tol, with_store, auto_tol);
        const std::string bytes = digest_bytes(file);
        const std::uint64_t n = bytes.size();
        out.append(reinterpret_cast<const char*>(&n), sizeof n).append(bytes);
      }
      return out;
    };
    auto take = [&](size_t r, std::string&& payload) {
      size_t at = 0;
      for (size_t f : requested[r]) {
        try {
          std::uint64_t n = 0;
          if (payload.size() - at < sizeof n)
            throw std::runtime_error("short answer from the loader process");
          std::memcpy(&n, payload.data() + at, sizeof n);
          at += sizeof n;
          if (payload.size() - at < n)
            throw std::runtime_error("short answer from the loader process");
          take_digest(payload.substr(at, n), mesh_files[f], with_store.meshes);
          at += n;
        } catch (const std::exception& e) {
          mesh_files[f].error = "cannot load mesh file " + requests[r].path + ": " + e.what();
        }
        done_file(f);
      }
    };
    auto failed = [&](size_t r, const std::string& why) {
      for (size_t f : requested[r]) {
        mesh_files[f].error = why;
        done_file(f);
      }
    };
    digest_meshes_isolated(requests, threads, load_timeout, load_memory_mb, before_load,
                           digest_request, take, failed);
  }
  // Hulls are independent: qhull_r keeps its state per run.
  parallel_for(unique.size(), threads, [&](size_t u) {
    built[u] = build_part(*unique[u], file_of[u] ? &mesh_files[*file_of[u]] : nullptr, with_store,
                          auto_tol);
    if (on_built && !file_of[u]) on_built(users[u]);
  });

  // Their reduced points are placed in the parts now. The heap would keep
  // them (the size of every hull again) for the rest of the run: back to the
  // system (the 15M scene's main process: 166 -> 85 MB).
  mesh_files.clear();
  malloc_trim(0);
  // A distinct part's last scene part takes it over: a copy per instance, not
  // one more of every hull (at 10^8 triangles the hulls are most of what
  // the parts stage keeps).
  std::vector<size_t> last_user(built.size(), 0);
  for (size_t k = 0; k < scene.parts.size(); ++k) last_user[source[k]] = k;
  std::vector<Part> parts;
  parts.reserve(scene.parts.size());
  const std::string units = scene.units.value_or("mm");
  for (size_t k = 0; k < scene.parts.size(); ++k) {
    Part p = last_user[source[k]] == k ? std::move(built[source[k]]) : built[source[k]];
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
      // Under auto nobody chose a tolerance, and each pair's band holds its
      // parts' coordinate steps.
      if (p.resolution && scene.tolerance && !scene.auto_tolerance)
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
  split_node_parts(scene, {threads, load_timeout, kAutoLoadMemory, {}, "", 256.0, {}, {}});
  if (tolerance) scene.tolerance = *tolerance;
  return build_parts(scene, threads, {}, load_timeout);
}

}  // namespace pd
