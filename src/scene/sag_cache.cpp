#include "scene/sag_cache.h"

#include <cmath>
#include <sstream>

#include "cache_file.h"
#include "hash.h"

namespace pd {

namespace {

constexpr CacheKind kKind{"pdcheck-sag-2", ".pds"};

}  // namespace

std::string sag_key(const std::string& content_hash, bool per_mesh) {
  Hasher h;
  h.add(kKind.format).add(content_hash).add(per_mesh ? 1.0 : 0.0);
  return h.hex();
}

// Body (hex floats round-trip exactly): "resolution concave convex creases
// design_edges features", then per feature "lo(3) hi(3) concave convex radius
// segments facets patches" and per patch "lo(3) hi(3) concave convex".
std::optional<TessellationSag> read_cached_sag(const std::string& dir, const std::string& key) {
  const std::optional<std::string> body = read_cache_entry(dir, kKind, key);
  if (!body) return std::nullopt;
  std::istringstream in(*body);
  TessellationSag s;
  long features = 0;
  // operator>> does not read hex floats portably: strtod does.
  const auto real = [&in](double& x) {
    std::string word;
    if (!(in >> word)) return false;
    char* end = nullptr;
    x = std::strtod(word.c_str(), &end);
    return end == word.c_str() + word.size() && std::isfinite(x);
  };
  if (!real(s.resolution) || !real(s.concave) || !real(s.convex) ||
      !(in >> s.creases >> s.design_edges >> features) || features < 0)
    return std::nullopt;
  for (long k = 0; k < features; ++k) {
    SagFeature f;
    for (int d = 0; d < 3; ++d)
      if (!real(f.box.lo(d))) return std::nullopt;
    for (int d = 0; d < 3; ++d)
      if (!real(f.box.hi(d))) return std::nullopt;
    long patches = 0;
    if (!real(f.concave) || !real(f.convex) || !real(f.radius) ||
        !(in >> f.segments >> f.facets >> patches) || patches < 0 || patches > f.facets)
      return std::nullopt;
    for (long q = 0; q < patches; ++q) {
      SagPatch p;
      for (int d = 0; d < 3; ++d)
        if (!real(p.box.lo(d))) return std::nullopt;
      for (int d = 0; d < 3; ++d)
        if (!real(p.box.hi(d))) return std::nullopt;
      if (!real(p.concave) || !real(p.convex)) return std::nullopt;
      f.patches.push_back(p);
    }
    s.features.push_back(f);
  }
  std::string rest;
  if (in >> rest) return std::nullopt;
  return s;
}

std::string write_cached_sag(const std::string& dir, const std::string& key,
                             const TessellationSag& s) {
  std::ostringstream body;
  body << std::hexfloat << s.resolution << ' ' << s.concave << ' ' << s.convex << ' ' << s.creases
       << ' ' << s.design_edges << ' ' << s.features.size() << '\n';
  for (const SagFeature& f : s.features) {
    for (int d = 0; d < 3; ++d) body << f.box.lo(d) << ' ';
    for (int d = 0; d < 3; ++d) body << f.box.hi(d) << ' ';
    body << f.concave << ' ' << f.convex << ' ' << f.radius << ' ' << f.segments << ' ' << f.facets
         << ' ' << f.patches.size() << '\n';
    for (const SagPatch& p : f.patches) {
      for (int d = 0; d < 3; ++d) body << p.box.lo(d) << ' ';
      for (int d = 0; d < 3; ++d) body << p.box.hi(d) << ' ';
      body << p.concave << ' ' << p.convex << '\n';
    }
  }
  return write_cache_entry(dir, kKind, key, body.str());
}

}  // namespace pd
