// Mesh files through assimp (STL, OBJ, PLY, glTF, …).
#pragma once

#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "brep/brep_file.h"
#include "geometry/mesh.h"
#include "geometry/types.h"

namespace pd {

/// A mesh file that cannot be used: unreadable, unknown format, no vertices.
class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Every mesh instance in a file (read in this process) with its triangles, node transforms applied
/// (world = node · v, accumulated in double precision: assimp stores float32).
/// With split_instances, one mesh per (node, mesh) instance; else one mesh
/// (triangle indices offset to the concatenated vertices). Faces of more than
/// three vertices are fanned; points and lines contribute vertices only.
/// `warnings`, when given, gets what the file holds that was skipped (a PLY
/// header line assimp skips, say), each naming the file.
std::vector<Mesh> load_meshes(const std::string& path, bool split_instances,
                              std::vector<std::string>* warnings = nullptr);

/// A file's mesh instances split by node (a scene part's `"split": "nodes"`):
/// every mesh instance on its own, placed as by load_meshes, with the path of
/// the node holding it: node names (scene/node_names.h: escaped, unnamed and
/// repeated siblings numbered) joined by '/', from the root's children down;
/// the root's own meshes are named by the root as if it were its first child.
struct NodeMeshes {
  std::vector<Mesh> meshes;
  std::vector<std::string> nodes;  ///< per mesh, its node path
  /// B-rep files (brep/brep_file.h), per mesh: the tessellation it carries,
  /// and why its leaf cannot be checked ("" when it can). Empty otherwise.
  std::vector<Tessellation> tessellations;
  std::vector<std::string> leaf_errors;
  /// B-rep files, per mesh: each triangle's face sag (BrepLeaf::triangle_sags).
  std::vector<std::vector<float>> triangle_sags;
};
NodeMeshes load_node_meshes(const std::string& path, std::vector<std::string>* warnings = nullptr);
/// load_node_meshes from a file's bytes (as read_meshes).
NodeMeshes read_node_meshes(std::string_view bytes, const std::string& extension,
                            std::vector<std::string>* warnings = nullptr);

/// A B-rep file (STEP, .brep: brep/brep_file.h) as meshes at linear deflection
/// `deflection` (file units: mm for STEP), each leaf instance with its node
/// path by the rules of load_node_meshes (the free shapes for the root's
/// children when the file has several, else the one free shape's components):
/// `by_node`, one mesh per leaf; else one mesh of them all, with their
/// combined tessellation (a leaf that cannot be checked is then the file's
/// error). Throws MeshError naming the file. `threads`: read_brep_file's.
NodeMeshes load_brep_meshes(const std::string& path, double deflection, bool by_node,
                            std::vector<std::string>* warnings = nullptr, int threads = 1);

/// load_brep_meshes' one mesh of a file's leaves (`by_node` false) from its
/// meshes by node: the meshes joined, their tessellations combined, the
/// triangles' sags in the joined order; a leaf that cannot be checked is the
/// file's error (MeshError).
NodeMeshes join_brep_leaves(NodeMeshes by_node);

/// One mesh of `pieces`: vertices concatenated, triangle indices offset.
Mesh join_meshes(const std::vector<Mesh>& pieces);

/// Reads a mesh file's bytes in this process (no time limit, no isolation; for
/// tests of the PLY check: runs read files by path, load_meshes): a PLY (recognized by its first
/// line, whatever the hint) is checked and, where Debian's assimp 5.2.5 would misread it, handed
/// over rewritten (scene/ply_check.h); then assimp reads from memory. `extension` is the format
/// hint for assimp ("stl", "obj", "ply", "glb", …). Returns what load_meshes returns; throws
/// MeshError with the reason (the caller names the file). A glTF with external buffers needs
/// load_meshes.
std::vector<Mesh> read_meshes(std::string_view bytes, const std::string& extension,
                              bool split_instances, std::vector<std::string>* warnings = nullptr);

/// Default limit, in seconds, on reading one mesh file in a loader process
/// (--load-timeout). Generous: assimp reads STL at tens of MB/s and a large
/// CAD part is rarely over 100 MB; a reader stuck in a loop is what it stops.
constexpr double kDefaultLoadTimeout = 60.0;

/// --load-memory's default: each loader process may allocate an equal share of
/// half the machine's memory (or its container's limit), so loaders reading
/// damaged files cannot drive the machine into its OOM killer together
/// (memory_limit.h). A positive value is MB per loader; 0 is no limit.
constexpr double kAutoLoadMemory = -1.0;

/// One file for load_meshes_isolated.
struct LoadedMeshes;

struct MeshRequest {
  std::string path;
  bool split_instances = false;
  /// load_node_meshes: every instance with its node path (LoadedMeshes::nodes).
  bool by_node = false;
  /// With by_node: only the distinct node paths, in file order, no meshes (the
  /// loader reads the whole file; only the names cross the pipe).
  bool node_names_only = false;
  /// B-rep files: the linear deflection to mesh them at (file units).
  double deflection = 0.0;
  /// With by_node, a B-rep file read whole for its names (split_node_parts):
  /// its meshes cross the pipe only when they take at most this many bytes,
  /// else the names alone do (node_names_only).
  double keep_bytes = INFINITY;
  /// The file as this process read it already, by node at `deflection`
  /// (split_node_parts: SceneSpec::brep_reads): a loader, forked from this
  /// process, takes it as read (joined when not `by_node`) and reads nothing.
  const LoadedMeshes* read = nullptr;
  /// With `read`: only its mesh at this index is taken (one node of a B-rep
  /// read, whose nodes are one leaf each); -2: none (a node it lacks).
  int node_mesh = -1;
  /// B-rep files: the cache entry of the file's read by node at `deflection`
  /// (key brep_read_cache_key, in the cache directory `read_cache_dir`): taken
  /// from there when it is whole, else the file is read and the entry stored,
  /// so that a rerun meshes nothing. An empty directory: no entry.
  std::string read_cache_dir = {}, read_cache_key = {};
};

/// The key of a B-rep file read at a deflection (SceneSpec::brep_reads).
std::string brep_read_key(const std::string& path, double deflection);

/// The cache key of a B-rep file's read by node at `deflection`
/// (MeshRequest::read_cache_key): its path too, which the reader's messages
/// name, its content hash, and brep_mesh_version().
std::string brep_read_cache_key(const std::string& path, const std::string& content_hash,
                                double deflection);

/// What load_meshes returned, or why the file cannot be used (names the file).
struct LoadedMeshes {
  std::vector<Mesh> meshes;
  std::optional<std::string> error;
  std::vector<std::string> warnings;  ///< load_meshes' warnings
  /// by_node: per mesh its node path; node_names_only: the distinct paths.
  std::vector<std::string> nodes;
  /// B-rep files: NodeMeshes' tessellations and leaf_errors (per mesh, or per
  /// distinct path when node_names_only).
  std::vector<Tessellation> tessellations;
  std::vector<std::string> leaf_errors;
  std::vector<std::vector<float>> triangle_sags;  ///< B-rep files: NodeMeshes' (per mesh)
};

/// Tests only (fault injection): runs in a loader process before it reads the
/// file at `path`, to make the reader crash or hang. The product never sets it.
using MeshLoadHook = std::function<void(const std::string& path)>;

/// load_meshes on each file in up to `jobs` loader processes: a file whose
/// reader crashes, runs longer than `timeout` seconds (0 = no limit), or
/// allocates more than `memory_mb` MB (kAutoLoadMemory: a share of the
/// machine's; 0 = no limit) gets an error and costs nothing else. Forks: call
/// it from a process with one thread (see mesh_loader_processes.cpp).
/// `on_file`, when given, is called (in this process) as each file is done.
std::vector<LoadedMeshes> load_meshes_isolated(const std::vector<MeshRequest>& files, int jobs,
                                               double timeout = kDefaultLoadTimeout,
                                               double memory_mb = kAutoLoadMemory,
                                               const MeshLoadHook& before_load = {},
                                               const std::function<void()>& on_file = {});

/// What a loader process makes of a file it has read (runs there, may hull,
/// measure and store what it read): the bytes the parent needs of it.
using MeshDigest = std::function<std::string(size_t request, LoadedMeshes&& read)>;

/// Reads every file as load_meshes_isolated does and hands what was read to
/// `digest` in the loader process; the parent gets the bytes in `take`, or in
/// `failed` why there are none (a message naming the file: the loader crashed,
/// ran out of time or memory, or `digest` threw). The meshes never cross to
/// the parent: what it holds of a file is what `digest` keeps.
void digest_meshes_isolated(const std::vector<MeshRequest>& files, int jobs, double timeout,
                            double memory_mb, const MeshLoadHook& before_load,
                            const MeshDigest& digest,
                            const std::function<void(size_t, std::string&&)>& take,
                            const std::function<void(size_t, const std::string&)>& failed);

/// The vertices of load_meshes, without triangles.
std::vector<Points> load_mesh_vertices(const std::string& path, bool split_instances);

}  // namespace pd
