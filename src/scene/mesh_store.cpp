#include "scene/mesh_store.h"

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "cache_file.h"
#include "geometry/same_position.h"

namespace pd {

namespace {

// The body: vertex count, triangle count, 4 or 8 (bytes per coordinate), then
// the coordinates and the corner indices as stored in memory (a store is read
// on the machine that wrote it, or is a miss: the key names the layout).
constexpr CacheKind kMeshKind{"pdcheck-mesh-2", ".pdm"};
// Per-triangle floats: their count, then the values as stored in memory.
constexpr CacheKind kSagsKind{"pdcheck-sags-1", ".pds"};
// A hull: vertex count, facet count, then the vertices (doubles), the facets'
// corners (ints) and their unit normals (doubles), as stored in memory.
constexpr CacheKind kHullKind{"pdcheck-hull-1", ".pdh"};

bool fits_float(const Points& p) {
  const double* d = p.data();
  for (Eigen::Index k = 0; k < p.size(); ++k)
    if (double(float(d[k])) != d[k] && !std::isnan(d[k])) return false;
  return true;
}

template <class T>
void put_raw(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

}  // namespace

std::shared_ptr<const MeshStore> MeshStore::in_cache(const std::string& cache_dir) {
  return std::shared_ptr<const MeshStore>(
      new MeshStore((std::filesystem::path(cache_dir) / "meshes").string(), 0));
}

std::shared_ptr<const MeshStore> MeshStore::temporary() {
  std::error_code ec;
  std::filesystem::path base = std::filesystem::temp_directory_path(ec);
  if (ec) base = "/tmp";
  std::string pattern = (base / "pdcheck-meshes-XXXXXX").string();
  const TerminationBlocked blocked;  // made and tracked before a signal can come
  if (!::mkdtemp(pattern.data()))
    throw std::runtime_error("cannot make a temporary directory for meshes in " + base.string() +
                             ": " + std::strerror(errno));
  auto store = std::shared_ptr<MeshStore>(new MeshStore(pattern, long(::getpid())));
  store->tracked_.track(pattern);
  return store;
}

MeshStore::~MeshStore() {
  if (owner_ == 0 || owner_ != long(::getpid())) return;
  std::error_code ec;
  std::filesystem::remove_all(dir_, ec);  // best effort: a temporary folder
}

long long MeshStore::stored_bytes(long vertices, long triangles) {
  return 64 + 24LL * vertices + 12LL * triangles;
}

std::string MeshStore::put(const std::string& key, const Mesh& input,
                           const std::vector<int>* first) const {
  const bool given = first && first->size() == size_t(input.vertices.cols());
  const Mesh mesh = welded(input, given ? *first : first_at_same_position(input.vertices));
  const bool f32 = fits_float(mesh.vertices);
  std::string body;
  body.reserve(size_t(stored_bytes(mesh.vertices.cols(), mesh.triangles.cols())));
  put_raw(body, std::int64_t(mesh.vertices.cols()));
  put_raw(body, std::int64_t(mesh.triangles.cols()));
  put_raw(body, std::int32_t(f32 ? 4 : 8));
  if (f32) {
    const Eigen::Matrix<float, 3, Eigen::Dynamic> v = mesh.vertices.cast<float>();
    body.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(float));
  } else {
    body.append(reinterpret_cast<const char*>(mesh.vertices.data()),
                mesh.vertices.size() * sizeof(double));
  }
  body.append(reinterpret_cast<const char*>(mesh.triangles.data()),
              mesh.triangles.size() * sizeof(int));
  return write_cache_entry(dir_, kMeshKind, key, body);
}

std::string MeshStore::put_sags(const std::string& key, const std::vector<float>& sags) const {
  std::string body;
  put_raw(body, std::int64_t(sags.size()));
  body.append(reinterpret_cast<const char*>(sags.data()), sags.size() * sizeof(float));
  return write_cache_entry(dir_, kSagsKind, key, body);
}

std::optional<std::vector<float>> MeshStore::get_sags(const std::string& key) const {
  const std::optional<std::string> body = read_cache_entry(dir_, kSagsKind, key);
  if (!body) return std::nullopt;
  std::int64_t n = 0;
  if (body->size() < sizeof n) return std::nullopt;
  std::memcpy(&n, body->data(), sizeof n);
  if (n < 0 || body->size() != sizeof n + size_t(n) * sizeof(float)) return std::nullopt;
  std::vector<float> out(static_cast<size_t>(n));
  if (n > 0) std::memcpy(out.data(), body->data() + sizeof n, size_t(n) * sizeof(float));
  return out;
}

std::string MeshStore::put_hull(const std::string& key, const Points& vertices,
                                const HullTriangles& facets) const {
  std::string body;
  const size_t nv = size_t(vertices.cols()), nt = facets.triangles.size();
  if (facets.normals.size() != nt) return "a hull's facets and normals differ in number";
  body.reserve(16 + nv * 24 + nt * (12 + 24));
  put_raw(body, std::int64_t(nv));
  put_raw(body, std::int64_t(nt));
  body.append(reinterpret_cast<const char*>(vertices.data()), nv * 3 * sizeof(double));
  body.append(reinterpret_cast<const char*>(facets.triangles.data()),
              nt * sizeof(facets.triangles[0]));
  for (const Vec3& n : facets.normals)
    body.append(reinterpret_cast<const char*>(n.data()), 3 * sizeof(double));
  return write_cache_entry(dir_, kHullKind, key, body);
}

std::optional<std::pair<Points, HullTriangles>> MeshStore::get_hull(const std::string& key) const {
  const std::optional<std::string> body = read_cache_entry(dir_, kHullKind, key);
  if (!body) return std::nullopt;
  const std::string& b = *body;
  std::int64_t nv = 0, nt = 0;
  if (b.size() < sizeof nv + sizeof nt) return std::nullopt;
  std::memcpy(&nv, b.data(), sizeof nv);
  std::memcpy(&nt, b.data() + sizeof nv, sizeof nt);
  if (nv < 0 || nt < 0 ||
      b.size() != sizeof nv + sizeof nt + size_t(nv) * 3 * sizeof(double) +
                      size_t(nt) * (sizeof(std::array<int, 3>) + 3 * sizeof(double)))
    return std::nullopt;
  std::pair<Points, HullTriangles> out;
  Points& v = out.first;
  HullTriangles& f = out.second;
  v.resize(3, nv);
  f.triangles.resize(size_t(nt));
  f.normals.resize(size_t(nt));
  const char* at = b.data() + sizeof nv + sizeof nt;
  if (nv > 0) std::memcpy(v.data(), at, size_t(nv) * 3 * sizeof(double));
  at += size_t(nv) * 3 * sizeof(double);
  if (nt > 0) std::memcpy(f.triangles.data(), at, size_t(nt) * sizeof(std::array<int, 3>));
  at += size_t(nt) * sizeof(std::array<int, 3>);
  for (Vec3& n : f.normals) {
    std::memcpy(n.data(), at, 3 * sizeof(double));
    at += 3 * sizeof(double);
  }
  for (const auto& t : f.triangles)  // a garbled index is a miss
    for (int k : t)
      if (k < 0 || k >= nv) return std::nullopt;
  return out;
}

std::optional<Mesh> MeshStore::get(const std::string& key) const {
  const std::optional<std::string> body = read_cache_entry(dir_, kMeshKind, key);
  if (!body) return std::nullopt;
  const std::string& b = *body;
  std::int64_t nv = 0, nt = 0;
  std::int32_t width = 0;
  constexpr size_t head = sizeof nv + sizeof nt + sizeof width;
  if (b.size() < head) return std::nullopt;
  std::memcpy(&nv, b.data(), sizeof nv);
  std::memcpy(&nt, b.data() + sizeof nv, sizeof nt);
  std::memcpy(&width, b.data() + sizeof nv + sizeof nt, sizeof width);
  if (nv < 0 || nt < 0 || (width != 4 && width != 8) ||
      b.size() != head + size_t(nv) * 3 * size_t(width) + size_t(nt) * 3 * sizeof(int))
    return std::nullopt;
  Mesh m;
  m.vertices.resize(3, nv);
  m.triangles.resize(3, nt);
  const char* at = b.data() + head;
  if (width == 4) {  // each float widened in place: no float copy of them all
    double* out = m.vertices.data();
    for (Eigen::Index k = 0; k < m.vertices.size(); ++k) {
      float f;
      std::memcpy(&f, at + size_t(k) * sizeof(float), sizeof f);
      out[k] = f;
    }
  } else if (nv > 0) {
    std::memcpy(m.vertices.data(), at, size_t(m.vertices.size()) * sizeof(double));
  }
  at += size_t(nv) * 3 * size_t(width);
  if (nt > 0) std::memcpy(m.triangles.data(), at, size_t(m.triangles.size()) * sizeof(int));
  for (Eigen::Index k = 0; k < m.triangles.size(); ++k)  // a garbled index is a miss
    if (m.triangles.data()[k] < 0 || m.triangles.data()[k] >= nv) return std::nullopt;
  return m;
}

// The entry's three lines and the body's head, and the file's size: an entry
// cut short (or grown) is not there. Its checksum is get()'s to check.
bool MeshStore::has(const std::string& key) const {
  std::ifstream in(std::filesystem::path(dir_) / (key + kMeshKind.extension), std::ios::binary);
  std::string format, stored_key, checksum;
  if (!std::getline(in, format) || format != kMeshKind.format || !std::getline(in, stored_key) ||
      stored_key != key || !std::getline(in, checksum))
    return false;
  std::int64_t nv = 0, nt = 0;
  std::int32_t width = 0;
  in.read(reinterpret_cast<char*>(&nv), sizeof nv);
  in.read(reinterpret_cast<char*>(&nt), sizeof nt);
  in.read(reinterpret_cast<char*>(&width), sizeof width);
  if (!in || nv < 0 || nt < 0 || (width != 4 && width != 8)) return false;
  const std::streamoff body = in.tellg();
  in.seekg(0, std::ios::end);
  return in.tellg() == body + std::streamoff(nv * 3 * width + nt * 3 * std::int64_t(sizeof(int)));
}

}  // namespace pd
