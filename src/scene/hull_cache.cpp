#include "scene/hull_cache.h"

#include <sstream>

#include "cache_file.h"
#include "geometry/point_bytes.h"
#include "hash.h"

namespace pd {

namespace {

constexpr CacheKind kKind{"pdcheck-hulls-1", ".pdh"};

}  // namespace

std::string hulls_key(const std::string& content_hash, bool per_mesh) {
  Hasher h;
  h.add(kKind.format).add(content_hash).add(per_mesh ? 1.0 : 0.0);
  return h.hex();
}

// Body: the counts on one line ("n c1 … cn"), then the point-set bytes.
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
  auto sets = point_sets_from_bytes(*entry, eol + 1, n);
  if (!sets) return std::nullopt;
  h.reduced = std::move(*sets);
  return h;
}

std::string write_cached_hulls(const std::string& dir, const std::string& key,
                               const StoredHulls& h) {
  std::ostringstream head;
  head << h.reduced.size();
  for (long c : h.counts) head << ' ' << c;
  head << '\n';
  return write_cache_entry(dir, kKind, key, head.str() + point_sets_bytes(h.reduced));
}

}  // namespace pd
