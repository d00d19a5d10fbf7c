#include "scene/hull_cache.h"

#include <sstream>

#include "cache_file.h"
#include "geometry/point_bytes.h"
#include "hash.h"

namespace pd {

namespace {

constexpr CacheKind kKind{"pdcheck-hulls-2", ".pdh"};
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

}  // namespace

std::string hulls_key(const std::string& content_hash, bool per_mesh) {
  Hasher h;
  h.add(kKind.format).add(content_hash).add(per_mesh ? 1.0 : 0.0);
  return h.hex();
}

// Body: the counts on one line ("n c1 … cn w"), w warning lines, then the
// point-set bytes.
std::optional<StoredHulls> read_cached_hulls(const std::string& dir, const std::string& key) {
  const std::optional<std::string> entry = read_cache_entry(dir, kKind, key);
  if (!entry) return std::nullopt;
  const size_t eol = entry->find('\n');
  if (eol == std::string::npos) return std::nullopt;
  std::istringstream head(entry->substr(0, eol));
  long n = 0;
  if (!(head >> n) || n < 1) return std::nullopt;
  StoredHulls h;
  for (long k = 0; k < n; ++k) {
    long c = 0;
    if (!(head >> c) || c < 0) return std::nullopt;
    h.counts.push_back(c);
  }
  long warnings = 0;
  if (!(head >> warnings) || warnings < 0) return std::nullopt;
  const size_t at = read_warning_lines(*entry, eol + 1, warnings, h.warnings);
  if (at == std::string::npos) return std::nullopt;
  auto sets = point_sets_from_bytes(*entry, at, n);
  if (!sets) return std::nullopt;
  h.reduced = std::move(*sets);
  return h;
}

std::string write_cached_hulls(const std::string& dir, const std::string& key,
                               const StoredHulls& h) {
  std::ostringstream head;
  head << h.reduced.size();
  for (long c : h.counts) head << ' ' << c;
  head << ' ' << h.warnings.size() << '\n' << warning_lines(h.warnings);
  return write_cache_entry(dir, kKind, key, head.str() + point_sets_bytes(h.reduced));
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
