#include "scene/hull_cache.h"

#include <cmath>
#include <cstring>
#include <sstream>
#include <type_traits>

#include "cache_file.h"
#include "geometry/point_bytes.h"
#include "hash.h"

namespace pd {

namespace {

// 3: the sag inside (before: a `.pds` entry of its own per file).
constexpr CacheKind kHullCache{"pdcheck-hulls-4", ".pdh"};  // 4: open-mesh warnings
constexpr CacheKind kInlineKind{"pdcheck-inline-hull-1", ".pdi"};

/// One line per warning (a line end inside one becomes a space).
std::string warning_lines(const std::vector<std::string>& warnings) {
  std::string out;
  for (const std::string& w : warnings) {
    for (char c : w) out += c == '\n' ? ' ' : c;
    out += '\n';
  }
  return out;
}

/// `n` lines from `at` into `out`; the offset past them, or npos when cut short.
size_t read_warning_lines(const std::string& e, size_t at, long n, std::vector<std::string>& out) {
  for (long k = 0; k < n; ++k) {
    const size_t eol = e.find('\n', at);
    if (eol == std::string::npos) return std::string::npos;
    out.push_back(e.substr(at, eol - at));
    at = eol + 1;
  }
  return at;
}

// The sag as bytes (doubles and counts as stored in memory, as the point sets
// are: exact, and read without parsing): "resolution concave convex creases
// design_edges features", then per feature "lo(3) hi(3) concave convex radius
// segments facets patches" and per patch "lo(3) hi(3) concave convex".
class SagWriter {
 public:
  template <class T>
  SagWriter& put(T x) {
    static_assert(std::is_arithmetic_v<T>);
    out_.append(reinterpret_cast<const char*>(&x), sizeof x);
    return *this;
  }
  SagWriter& put(const Vec3& v) { return put(v.x()).put(v.y()).put(v.z()); }
  std::string bytes() && { return std::move(out_); }

 private:
  std::string out_;
};

std::string sag_bytes(const TessellationSag& s) {
  SagWriter w;
  w.put(s.resolution).put(s.concave).put(s.convex).put<long>(s.creases).put<long>(s.design_edges);
  w.put<long>(static_cast<long>(s.features.size()));
  for (const SagFeature& f : s.features) {
    w.put(f.box.lo).put(f.box.hi).put(f.concave).put(f.convex).put(f.radius);
    w.put<long>(f.segments).put<long>(f.facets).put<long>(static_cast<long>(f.patches.size()));
    for (const SagPatch& p : f.patches) w.put(p.box.lo).put(p.box.hi).put(p.concave).put(p.convex);
  }
  return std::move(w).bytes();
}

// Reads what sag_bytes wrote from `e` at `at` (advanced past it); false when
// it is cut short or holds a non-finite length or an impossible count.
class SagReader {
 public:
  SagReader(const std::string& e, size_t& at) : e_(e), at_(at) {}
  template <class T>
  bool get(T& x) {
    if (e_.size() - at_ < sizeof x) return false;
    std::memcpy(&x, e_.data() + at_, sizeof x);
    at_ += sizeof x;
    if constexpr (std::is_floating_point_v<T>) return std::isfinite(x);
    return true;
  }
  bool get(Vec3& v) { return get(v.x()) && get(v.y()) && get(v.z()); }
  /// A count of items of at least `item` bytes each that the rest can hold.
  bool count(long& n, size_t item) {
    return get(n) && n >= 0 && static_cast<size_t>(n) <= (e_.size() - at_) / item;
  }

 private:
  const std::string& e_;
  size_t& at_;
};

std::optional<TessellationSag> sag_from_bytes(const std::string& e, size_t& at) {
  SagReader r(e, at);
  TessellationSag s;
  long features = 0;
  if (!r.get(s.resolution) || !r.get(s.concave) || !r.get(s.convex) || !r.get(s.creases) ||
      !r.get(s.design_edges) || !r.count(features, 12 * sizeof(double)))
    return std::nullopt;
  s.features.resize(static_cast<size_t>(features));
  for (SagFeature& f : s.features) {
    long segments = 0, patches = 0;
    if (!r.get(f.box.lo) || !r.get(f.box.hi) || !r.get(f.concave) || !r.get(f.convex) ||
        !r.get(f.radius) || !r.get(segments) || !r.get(f.facets) ||
        !r.count(patches, 8 * sizeof(double)) || patches > f.facets ||
        segments != static_cast<int>(segments))
      return std::nullopt;
    f.segments = static_cast<int>(segments);
    f.patches.resize(static_cast<size_t>(patches));
    for (SagPatch& p : f.patches)
      if (!r.get(p.box.lo) || !r.get(p.box.hi) || !r.get(p.concave) || !r.get(p.convex))
        return std::nullopt;
  }
  return s;
}

}  // namespace

std::string hulls_key(const std::string& content_hash, bool per_mesh) {
  Hasher h;
  h.add(kHullCache.format).add(content_hash).add(per_mesh ? 1.0 : 0.0);
  return h.hex();
}

// Body: the counts on one line ("n c1 … cn w s"), w warning lines, the sag's
// bytes when s is 1, then the point-set bytes.
std::optional<StoredHulls> stored_hulls_from_bytes(const std::string& entry) {
  const size_t eol = entry.find('\n');
  if (eol == std::string::npos) return std::nullopt;
  std::istringstream head(entry.substr(0, eol));
  long n = 0;
  if (!(head >> n) || n < 1) return std::nullopt;
  StoredHulls h;
  for (long k = 0; k < n; ++k) {
    long c = 0;
    if (!(head >> c) || c < 0) return std::nullopt;
    h.counts.push_back(c);
  }
  long warnings = 0;
  int has_sag = 0;
  if (!(head >> warnings >> has_sag) || warnings < 0 || (has_sag != 0 && has_sag != 1))
    return std::nullopt;
  size_t at = read_warning_lines(entry, eol + 1, warnings, h.warnings);
  if (at == std::string::npos) return std::nullopt;
  if (has_sag) {
    h.sag = sag_from_bytes(entry, at);
    if (!h.sag) return std::nullopt;
  }
  auto sets = point_sets_from_bytes(entry, at, n);
  if (!sets) return std::nullopt;
  h.reduced = std::move(*sets);
  return h;
}

std::string stored_hulls_bytes(const StoredHulls& h) {
  std::ostringstream head;
  head << h.reduced.size();
  for (long c : h.counts) head << ' ' << c;
  head << ' ' << h.warnings.size() << ' ' << (h.sag ? 1 : 0) << '\n' << warning_lines(h.warnings);
  return head.str() + (h.sag ? sag_bytes(*h.sag) : std::string()) + point_sets_bytes(h.reduced);
}

std::optional<StoredHulls> read_cached_hulls(const std::string& dir, const std::string& key) {
  const std::optional<std::string> entry = read_cache_entry(dir, kHullCache, key);
  if (!entry) return std::nullopt;
  return stored_hulls_from_bytes(*entry);
}

std::string write_cached_hulls(const std::string& dir, const std::string& key,
                               const StoredHulls& h) {
  return write_cache_entry(dir, kHullCache, key, stored_hulls_bytes(h));
}

std::string inline_hull_key(const std::string& digest, double to_scene_units,
                            const Mat4& transform) {
  Hasher h;
  h.add(kInlineKind.format).add(digest).add(to_scene_units);
  for (int k = 0; k < 16; ++k) h.add(transform(k / 4, k % 4));
  return h.hex();
}

// Body: "dimension warnings" line, one line per warning, then the vertices' bytes.
std::optional<Hull> read_cached_hull(const std::string& dir, const std::string& key) {
  const std::optional<std::string> entry = read_cache_entry(dir, kInlineKind, key);
  if (!entry) return std::nullopt;
  const std::string& e = *entry;
  const size_t eol = e.find('\n');
  if (eol == std::string::npos) return std::nullopt;
  std::istringstream head(e.substr(0, eol));
  Hull h;
  long warnings = 0;
  if (!(head >> h.dimension >> warnings) || h.dimension < 0 || h.dimension > 3 || warnings < 0)
    return std::nullopt;
  const size_t at = read_warning_lines(e, eol + 1, warnings, h.warnings);
  if (at == std::string::npos) return std::nullopt;
  auto sets = point_sets_from_bytes(e, at, 1);
  if (!sets) return std::nullopt;
  h.vertices = std::move((*sets)[0]);
  return h;
}

std::string write_cached_hull(const std::string& dir, const std::string& key, const Hull& h) {
  std::ostringstream head;
  head << h.dimension << ' ' << h.warnings.size() << '\n' << warning_lines(h.warnings);
  return write_cache_entry(dir, kInlineKind, key, head.str() + point_sets_bytes({h.vertices}));
}

}  // namespace pd
