// Mesh files read in loader processes, under a time limit.
//
// Why processes: assimp can loop forever (5.2.5 spins at 100 % CPU on a PLY
// cut inside its header) or crash on a damaged file, and a thread cannot be
// stopped or survive a crash; a process can be killed and its death observed.
//
// Why the work queue, forked before any thread: build_parts hulls on a thread
// pool, and a fork from a multithreaded process copies every lock another
// thread holds at that instant (libstdc++'s locale mutex taken by any stream,
// assimp's logger, the pool's own queue) into a child where no thread will
// ever release it; glibc makes malloc safe across fork, nothing makes those
// safe. So every file is read here, before the pool starts, by the process
// work queue (src/work_queue.h): it forks its workers from this single-thread
// process, replaces one that crashed or timed out the same way, and gives
// each task its own time limit. Alternatives weighed: posix_spawn of our own
// binary is as safe but needs the executable's path from every program that
// links the library (tests, pdbench) and pays exec and dynamic linking per
// loader; a fork server (a zygote forked at start) needs descriptor passing
// for the same result. The cost here: the meshes cross a pipe once, and the
// reads end before the hulls start (measured in docs/performance.md).
#include <malloc.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <new>
#include <optional>

#include "brep/brep_backend.h"
#include "cache_file.h"
#include "memory_limit.h"
#include "scene/mesh_loader.h"
#include "work_queue.h"

namespace pd {

namespace {

// A payload: 'E' and the reason, or 'M', the mesh count, then per mesh its
// vertex and triangle counts and raw arrays, then the warning count and per
// warning its length and bytes, then the node path count and the paths alike,
// then the tessellation count and each as raw bytes, then the leaf errors as
// the paths (this machine's byte order: the reader is a fork of the writer).
template <class T>
void put(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

void put_strings(std::string& out, const std::vector<std::string>& list) {
  put(out, std::uint64_t(list.size()));
  for (const std::string& w : list) {
    put(out, std::uint64_t(w.size()));
    out += w;
  }
}

std::string encode(const std::vector<Mesh>& meshes, const std::vector<std::string>& warnings,
                   const std::vector<std::string>& nodes,
                   const std::vector<Tessellation>& tessellations = {},
                   const std::vector<std::string>& leaf_errors = {},
                   const std::vector<std::vector<float>>& triangle_sags = {}) {
  size_t bytes = 1 + 8;
  for (const Mesh& m : meshes)
    bytes += 16 + m.vertices.size() * sizeof(double) + m.triangles.size() * sizeof(int);
  std::string out;
  out.reserve(bytes);
  out += 'M';
  put(out, std::uint64_t(meshes.size()));
  for (const Mesh& m : meshes) {
    put(out, std::int64_t(m.vertices.cols()));
    put(out, std::int64_t(m.triangles.cols()));
    out.append(reinterpret_cast<const char*>(m.vertices.data()),
               m.vertices.size() * sizeof(double));
    out.append(reinterpret_cast<const char*>(m.triangles.data()), m.triangles.size() * sizeof(int));
  }
  put_strings(out, warnings);
  put_strings(out, nodes);
  put(out, std::uint64_t(tessellations.size()));
  for (const Tessellation& t : tessellations) put(out, t);
  put_strings(out, leaf_errors);
  put(out, std::uint64_t(triangle_sags.size()));
  for (const std::vector<float>& v : triangle_sags) {
    put(out, std::uint64_t(v.size()));
    out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(float));
  }
  return out;
}

struct Reader {
  const std::string& s;
  size_t at = 1;
  void take(void* to, size_t n) {
    if (s.size() - at < n) throw std::runtime_error("short answer from the loader process");
    if (n > 0) std::memcpy(to, s.data() + at, n);  // `to` may be an empty vector's null data()
    at += n;
  }
  template <class T>
  T get() {
    T v;
    take(&v, sizeof v);
    return v;
  }
  std::vector<std::string> strings() {
    std::vector<std::string> out;
    const auto n = get<std::uint64_t>();
    for (std::uint64_t k = 0; k < n; ++k) {
      const auto len = get<std::uint64_t>();
      if (len > s.size()) throw std::runtime_error("malformed answer from the loader process");
      std::string w(len, '\0');
      take(w.data(), len);
      out.push_back(std::move(w));
    }
    return out;
  }
};

LoadedMeshes decode(const std::string& payload) {
  LoadedMeshes out;
  if (payload.empty()) throw std::runtime_error("empty answer from the loader process");
  if (payload[0] == 'E') {
    out.error = payload.substr(1);
    return out;
  }
  Reader r{payload};
  const auto n = r.get<std::uint64_t>();
  for (std::uint64_t k = 0; k < n; ++k) {
    const auto nv = r.get<std::int64_t>(), nt = r.get<std::int64_t>();
    if (nv < 0 || nt < 0 || std::uint64_t(nv) > payload.size() ||
        std::uint64_t(nt) > payload.size())
      throw std::runtime_error("malformed answer from the loader process");
    Mesh m;
    m.vertices.resize(3, nv);
    m.triangles.resize(3, nt);
    r.take(m.vertices.data(), m.vertices.size() * sizeof(double));
    r.take(m.triangles.data(), m.triangles.size() * sizeof(int));
    out.meshes.push_back(std::move(m));
  }
  out.warnings = r.strings();
  out.nodes = r.strings();
  const auto tessellations = r.get<std::uint64_t>();
  if (tessellations > payload.size())
    throw std::runtime_error("malformed answer from the loader process");
  for (std::uint64_t k = 0; k < tessellations; ++k)
    out.tessellations.push_back(r.get<Tessellation>());
  out.leaf_errors = r.strings();
  const auto sagged = r.get<std::uint64_t>();
  if (sagged > payload.size()) throw std::runtime_error("malformed answer from the loader process");
  for (std::uint64_t k = 0; k < sagged; ++k) {
    const auto n = r.get<std::uint64_t>();
    if (n > payload.size()) throw std::runtime_error("malformed answer from the loader process");
    std::vector<float> v(n);
    r.take(v.data(), n * sizeof(float));
    out.triangle_sags.push_back(std::move(v));
  }
  return out;
}

std::string megabytes(double mb) {
  char b[32];
  std::snprintf(b, sizeof b, "%.0f", mb);
  return b;
}

// Sets up a loader process once: `memory_mb` > 0 caps what it may allocate
// (a loader reads many files and keeps its heap); true when capped.
bool loader_setup(double memory_mb) {
  static const bool capped = cap_address_space_growth(memory_mb);
  // assimp's line readers (OBJ, PLY) allocate and fill buffers of 4 MB per
  // line; glibc hands such blocks back to the kernel on free, so every read
  // paid for fresh zeroed pages (about 25 ms a PLY). A loader keeps its heap.
  static const bool tuned =
      mallopt(M_MMAP_THRESHOLD, 32 << 20) && mallopt(M_TRIM_THRESHOLD, 256 << 20);
  (void)tuned;
  return capped;
}

std::string out_of_memory(const std::string& path, bool capped, double memory_mb) {
  return "mesh file " + path + ": " +
         (capped
              ? "reading, hulling and measuring it needed more than the loader's memory limit of " +
                    megabytes(memory_mb) + " MB (--load-memory); damaged file?"
              : std::string("out of memory while loading (damaged file?)"));
}

// A B-rep file's read by node: its leaves' meshes as NodeMeshes.
NodeMeshes node_meshes(const LoadedMeshes& by_node) {
  return {by_node.meshes, by_node.nodes, by_node.tessellations, by_node.leaf_errors,
          by_node.triangle_sags};
}

// A B-rep read by node as the request asks for it: whole, or its leaves joined.
LoadedMeshes as_asked(const MeshRequest& f, const LoadedMeshes& by_node) {
  if (f.by_node) return by_node;
  LoadedMeshes out;
  NodeMeshes joined = join_brep_leaves(node_meshes(by_node));
  out.warnings = by_node.warnings;
  out.meshes = std::move(joined.meshes);
  out.tessellations = std::move(joined.tessellations);
  out.leaf_errors = std::move(joined.leaf_errors);
  out.triangle_sags = std::move(joined.triangle_sags);
  return out;
}

// The mesh at index `k` of a read by node, with its node path (none for k < 0).
LoadedMeshes one_mesh(const LoadedMeshes& by_node, int k) {
  LoadedMeshes out;
  out.warnings = by_node.warnings;
  if (k < 0 || size_t(k) >= by_node.meshes.size()) return out;
  const size_t m = size_t(k);
  out.meshes.push_back(by_node.meshes[m]);
  out.nodes.push_back(by_node.nodes[m]);
  if (m < by_node.tessellations.size()) out.tessellations.push_back(by_node.tessellations[m]);
  if (m < by_node.leaf_errors.size()) out.leaf_errors.push_back(by_node.leaf_errors[m]);
  if (m < by_node.triangle_sags.size()) out.triangle_sags.push_back(by_node.triangle_sags[m]);
  return out;
}

// B-rep reads in the cache directory: the loader's payload as it is, under
// brep_read_cache_key (the entry's checksum keeps a damaged one out).
constexpr CacheKind kBrepReadKind{"pdcheck-brep-read-1", ".pdb"};

// The request's B-rep read from its cache entry, when there is a whole one.
std::optional<LoadedMeshes> cached_brep_read(const MeshRequest& f) {
  if (f.read_cache_dir.empty()) return std::nullopt;
  const std::optional<std::string> body =
      read_cache_entry(f.read_cache_dir, kBrepReadKind, f.read_cache_key);
  if (!body) return std::nullopt;
  try {
    LoadedMeshes got = decode(*body);
    if (got.error) return std::nullopt;
    return got;
  } catch (const std::exception&) {
    return std::nullopt;  // a layout this build does not read: read the file again
  }
}

/// Runs in a loader process: the file as read, or why it cannot be. The test
/// hook runs just before the file itself is read (not for a read taken from
/// the process forked from or from the cache). A B-rep file is meshed on up
/// to `threads` threads.
LoadedMeshes read_one(const MeshRequest& f, bool capped, double memory_mb,
                      const MeshLoadHook& before_load, int threads) {
  LoadedMeshes out;
  try {
    const bool brep = is_brep_path(f.path);
    if (f.read)  // read by node in the process this one forked from
      return f.node_mesh != -1 ? one_mesh(*f.read, f.node_mesh) : as_asked(f, *f.read);
    if (!f.by_node && !brep) {
      if (before_load) before_load(f.path);
      out.meshes = load_meshes(f.path, f.split_instances, &out.warnings);
      return out;
    }
    // A B-rep file is read by node (or taken from its cache entry) and joined
    // as asked afterwards: the same meshes either way, and the entry serves both.
    NodeMeshes read;
    if (std::optional<LoadedMeshes> hit = brep ? cached_brep_read(f) : std::nullopt) {
      read = {std::move(hit->meshes), std::move(hit->nodes), std::move(hit->tessellations),
              std::move(hit->leaf_errors), std::move(hit->triangle_sags)};
      out.warnings = std::move(hit->warnings);
    } else {
      if (before_load) before_load(f.path);
      read = brep ? load_brep_meshes(f.path, f.deflection, true, &out.warnings, threads)
                  : load_node_meshes(f.path, &out.warnings);
      if (brep && !f.read_cache_dir.empty())  // best effort: a run without it reads the file again
        write_cache_entry(f.read_cache_dir, kBrepReadKind, f.read_cache_key,
                          encode(read.meshes, out.warnings, read.nodes, read.tessellations,
                                 read.leaf_errors, read.triangle_sags));
    }
    if (brep && !f.by_node) read = join_brep_leaves(std::move(read));
    double bytes = 0.0;  // what the meshes cost to hand over and keep
    for (size_t k = 0; k < read.meshes.size(); ++k)
      bytes += read.meshes[k].vertices.size() * sizeof(double) +
               read.meshes[k].triangles.size() * sizeof(int) +
               (k < read.triangle_sags.size() ? read.triangle_sags[k].size() * sizeof(float) : 0);
    if (!f.node_names_only && bytes <= f.keep_bytes) {
      out.meshes = std::move(read.meshes);
      out.nodes = std::move(read.nodes);
      out.tessellations = std::move(read.tessellations);
      out.leaf_errors = std::move(read.leaf_errors);
      out.triangle_sags = std::move(read.triangle_sags);
      return out;
    }
    // A node's meshes come together (collect_by_node), and paths are unique.
    for (std::string& n : read.nodes)
      if (out.nodes.empty() || out.nodes.back() != n) out.nodes.push_back(std::move(n));
    return out;
  } catch (const MeshError& e) {
    out = {};
    out.error = e.what();
  } catch (const std::bad_alloc&) {
    out = {};
    out.error = out_of_memory(f.path, capped, memory_mb);
  } catch (const std::exception& e) {
    out = {};
    out.error = "mesh file " + f.path + ": " + e.what();
  }
  return out;
}

std::string seconds(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", s);
  return b;
}

}  // namespace

void digest_meshes_isolated(const std::vector<MeshRequest>& files, int jobs, double timeout,
                            double memory_mb, const MeshLoadHook& before_load,
                            const MeshDigest& digest,
                            const std::function<void(size_t, std::string&&)>& take,
                            const std::function<void(size_t, const std::string&)>& failed) {
  const int loaders = std::max(1, jobs);
  if (memory_mb < 0) memory_mb = memory_share_mb(available_memory_mb(), loaders);
  // Largest files first: no loader idles at the end on a long tail.
  std::vector<size_t> order(files.size());
  std::vector<off_t> size(files.size(), 0);
  for (size_t k = 0; k < order.size(); ++k) {
    order[k] = k;
    struct stat st {};
    if (::stat(files[k].path.c_str(), &st) == 0) size[k] = st.st_size;
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return size[a] > size[b]; });
  // Fewer files than loaders (a STEP assembly is one file): each loader's
  // share of the cores meshes its B-rep products side by side.
  const int threads =
      files.empty() ? 1 : std::max(1, loaders / int(std::min(files.size(), size_t(loaders))));
  // Open CASCADE is loaded once here, before the loaders are forked, rather
  // than in each of them (brep/brep_backend.h), when a B-rep file is to be
  // read: not for one taken from this process's read or from its cache entry
  // (a rerun), where no loader calls it (one whose entry turns out damaged
  // loads it itself). A failure is each B-rep file's error.
  if (std::any_of(files.begin(), files.end(), [](const MeshRequest& f) {
        return is_brep_path(f.path) && !f.read &&
               !cache_entry_present(f.read_cache_dir, kBrepReadKind, f.read_cache_key);
      }))
    preload_brep_backend();
  auto task = [&](size_t k) {
    const bool capped = loader_setup(memory_mb);
    try {
      // The file is let go into the loader's heap, which the next file takes
      // again without a page fault per page; the largest files come first,
      // so what a loader holds after one is no more than it held during it.
      return "D" + digest(k, read_one(files[k], capped, memory_mb, before_load, threads));
    } catch (const std::bad_alloc&) {
      return "E" + out_of_memory(files[k].path, capped, memory_mb);
    } catch (const std::exception& e) {
      return "Emesh file " + files[k].path + ": " + e.what();
    }
  };
  auto done = [&](size_t k, bool ok, const std::string& payload) {
    const std::string& path = files[k].path;
    if (ok && !payload.empty() && payload[0] == 'D') return take(k, payload.substr(1));
    if (ok)
      return failed(k, payload.empty() ? "cannot load mesh file " + path +
                                             ": empty answer from the loader process"
                                       : payload.substr(1));
    const bool late = payload.rfind("timed out", 0) == 0;
    failed(k, "cannot load mesh file " + path + ": " +
                  (late ? "reading it took longer than the load limit of " + seconds(timeout) +
                              " s (--load-timeout); the loader was stopped"
                        : "the loader process failed: " + payload +
                              (memory_mb > 0 && can_cap_address_space()
                                   ? " (its memory limit was " + megabytes(memory_mb) +
                                         " MB, --load-memory)"
                                   : "")));
  };
  QueueOptions queue{loaders, timeout, {}, {}};
  run_work_queue(order, queue, task, done);
}

std::vector<LoadedMeshes> load_meshes_isolated(const std::vector<MeshRequest>& files, int jobs,
                                               double timeout, double memory_mb,
                                               const MeshLoadHook& before_load,
                                               const std::function<void()>& on_file) {
  std::vector<LoadedMeshes> out(files.size());
  auto digest = [](size_t, LoadedMeshes&& read) {
    if (read.error) return "E" + *read.error;
    return encode(read.meshes, read.warnings, read.nodes, read.tessellations, read.leaf_errors,
                  read.triangle_sags);
  };
  auto take = [&](size_t k, std::string&& payload) {
    try {
      out[k] = decode(payload);
    } catch (const std::exception& e) {
      out[k] = {};
      out[k].error = "cannot load mesh file " + files[k].path + ": " + e.what();
    }
    if (on_file) on_file();
  };
  auto failed = [&](size_t k, const std::string& why) {
    out[k].error = why;
    if (on_file) on_file();
  };
  digest_meshes_isolated(files, jobs, timeout, memory_mb, before_load, digest, take, failed);
  return out;
}

}  // namespace pd
