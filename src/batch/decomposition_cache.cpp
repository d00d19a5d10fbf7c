#include "batch/decomposition_cache.h"

#include <sstream>

#include "geometry/point_bytes.h"
#include "hash.h"
#include "tolerances.h"

namespace pd {

namespace {

// 3: the entry's fields moved into the checked body (cache_file.h).
constexpr CacheKind kDecompositionCache{"pdcheck-decomposition-3", ".pdd"};

}  // namespace

std::string decomposition_key(const std::string& content_hash, double concavity_tol,
                              double time_limit_seconds) {
  Hasher h;
  h.add(kDecompositionCache.format).add(content_hash).add(concavity_tol).add(time_limit_seconds);
  h.add(static_cast<double>(tol::kDecomposeMaxWork));
  return h.hex();
}

// Body: "complete seconds count" line, note line, then the piece bytes (count,
// then 3·count doubles, per piece).
std::optional<StoredDecomposition> read_cached_decomposition(const std::string& dir,
                                                             const std::string& key) {
  const std::optional<std::string> entry = read_cache_entry(dir, kDecompositionCache, key);
  if (!entry) return std::nullopt;
  const std::string& e = *entry;
  const size_t eol1 = e.find('\n');
  const size_t eol2 = eol1 == std::string::npos ? eol1 : e.find('\n', eol1 + 1);
  if (eol2 == std::string::npos) return std::nullopt;
  StoredDecomposition d;
  long count = 0;
  int complete = 0;
  std::istringstream hs(e.substr(0, eol1));
  if (!(hs >> complete >> d.seconds >> count) || count < 0) return std::nullopt;
  d.complete = complete != 0;
  d.note = e.substr(eol1 + 1, eol2 - eol1 - 1);
  auto pieces = point_sets_from_bytes(e, eol2 + 1, count);
  if (!pieces) return std::nullopt;
  d.pieces = std::move(*pieces);
  return d;
}

std::string write_cached_decomposition(const std::string& dir, const std::string& key,
                                       const StoredDecomposition& d) {
  std::string note = d.note;
  for (char& c : note)
    if (c == '\n') c = ' ';
  std::ostringstream head;
  head.precision(17);
  head << (d.complete ? 1 : 0) << " " << d.seconds << " " << d.pieces.size() << "\n"
       << note << "\n";
  return write_cache_entry(dir, kDecompositionCache, key, head.str() + point_sets_bytes(d.pieces));
}

}  // namespace pd
