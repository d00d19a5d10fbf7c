#include "scene/convexity_cache.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "cache_file.h"
#include "geometry/convexity.h"
#include "hash.h"

namespace pd {

namespace {

// 3: samples on the mesh's own faces are not measured (hull_concavity's on_part).
// 4: a coarse pass first (its value when it decides); samples within a quarter
//    of the tolerance of the faces count as on them.
constexpr CacheKind kConvexityCache{"pdcheck-convexity-4", ".pdv"};

}  // namespace

std::string convexity_key(const std::string& content_hash, double concavity_tol,
                          double stop_above) {
  Hasher h;
  h.add(kConvexityCache.format).add(content_hash).add(concavity_tol).add(stop_above);
  h.add(static_cast<double>(kConvexitySamples));
  return h.hex();
}

// Body: "<concavity as a hex float> <closed 0|1>" (hex floats round-trip exactly).
std::optional<StoredConvexity> read_cached_convexity(const std::string& dir,
                                                     const std::string& key) {
  const std::optional<std::string> body = read_cache_entry(dir, kConvexityCache, key);
  if (!body) return std::nullopt;
  char* end = nullptr;
  StoredConvexity c;
  c.concavity = std::strtod(body->c_str(), &end);
  if (end == body->c_str() || !std::isfinite(c.concavity) || c.concavity < 0) return std::nullopt;
  const std::string rest(end);
  if (rest != " 0" && rest != " 1") return std::nullopt;
  c.closed = rest == " 1";
  return c;
}

std::string write_cached_convexity(const std::string& dir, const std::string& key,
                                   const StoredConvexity& c) {
  std::ostringstream body;
  body << std::hexfloat << c.concavity << (c.closed ? " 1" : " 0");
  return write_cache_entry(dir, kConvexityCache, key, body.str());
}

}  // namespace pd
