// Parsed, welded meshes on disk, by key: the parts stage measures a surface
// and lets it go; the stages that need its triangles again (the nonconvex
// refinement, the HTML report) read it back from here. In a cache directory
// the store outlives the run (a rerun reads no mesh file again); without one
// it is a temporary directory of the run's own.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geometry/hull.h"
#include "geometry/mesh.h"
#include "termination.h"

namespace pd {

class MeshStore {
 public:
  /// The persistent store of the cache directory `cache_dir` (its "meshes"
  /// folder, made when first written).
  static std::shared_ptr<const MeshStore> in_cache(const std::string& cache_dir);
  /// A store of this run's own in a new temporary directory, removed with its
  /// last reference (by the process that made it, never by a forked child).
  /// Throws std::runtime_error when no temporary directory can be made.
  static std::shared_ptr<const MeshStore> temporary();
  ~MeshStore();
  MeshStore(const MeshStore&) = delete;
  MeshStore& operator=(const MeshStore&) = delete;

  const std::string& dir() const { return dir_; }
  bool persistent() const { return owner_ == 0; }

  /// Stores `mesh` under `key` welded (each position once: an STL file's
  /// corners are a sixth as many; geometry/same_position.h), in a file
  /// written whole or not at all: "" or why not. `first` is
  /// first_at_same_position of its vertices when the caller has it. Vertices
  /// exactly representable in float32 (a mesh file's, as assimp reads them)
  /// are stored as such, at half the bytes.
  std::string put(const std::string& key, const Mesh& mesh,
                  const std::vector<int>* first = nullptr) const;
  /// The mesh stored under `key` (welded), or nullopt when it is absent or
  /// not whole.
  std::optional<Mesh> get(const std::string& key) const;
  /// Stores per-triangle values of the mesh under `key` (a B-rep surface's
  /// face sags), beside it: "" or why not.
  std::string put_sags(const std::string& key, const std::vector<float>& sags) const;
  /// The values stored under `key`, or nullopt when absent or not whole.
  std::optional<std::vector<float>> get_sags(const std::string& key) const;
  /// Stores the mesh's hull as convex_hull found it (its vertices and facets)
  /// under `key`, beside it: "" or why not. Its convexity measure then needs
  /// no second qhull run.
  std::string put_hull(const std::string& key, const Points& vertices,
                       const HullTriangles& facets) const;
  /// The hull stored under `key`, or nullopt when absent or not whole.
  std::optional<std::pair<Points, HullTriangles>> get_hull(const std::string& key) const;
  /// Whether an entry is there (not read: get() checks it).
  bool has(const std::string& key) const;

  /// Bytes a mesh of this size takes on disk at most (double coordinates).
  static long long stored_bytes(long vertices, long triangles);

 private:
  MeshStore(std::string dir, long owner) : dir_(std::move(dir)), owner_(owner) {}
  std::string dir_;
  long owner_ = 0;          ///< the pid that removes a temporary store; 0: persistent
  TrackedTempDir tracked_;  ///< a temporary store: removed too when the run is terminated
};

/// A mesh the store holds: where, and under which key.
struct StoredMesh {
  std::shared_ptr<const MeshStore> store;
  std::string key;
};

}  // namespace pd
