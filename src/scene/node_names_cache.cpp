#include "scene/node_names_cache.h"

#include <sstream>

#include "cache_file.h"
#include "hash.h"

namespace pd {

namespace {

// The naming rules (node_names.h) and assimp's reading are part of the format:
// bump it when either changes.
constexpr CacheKind kNodeNamesCache{"pdcheck-node-names-1", ".pdn"};

}  // namespace

std::string node_names_key(const std::string& content_hash) {
  return Hasher().add(kNodeNamesCache.format).add(content_hash).hex();
}

// Body: the count, then per path its length in bytes and the bytes (a name
// may hold any byte, a line end too), each field on its own line.
std::optional<std::vector<std::string>> read_cached_node_names(const std::string& dir,
                                                               const std::string& key) {
  const std::optional<std::string> body = read_cache_entry(dir, kNodeNamesCache, key);
  if (!body) return std::nullopt;
  std::istringstream in(*body);
  long count = 0;
  if (!(in >> count) || count <= 0 || in.get() != '\n') return std::nullopt;
  std::vector<std::string> out;
  for (long k = 0; k < count; ++k) {
    long len = 0;
    if (!(in >> len) || len < 0 || len > long(body->size()) || in.get() != '\n')
      return std::nullopt;
    std::string name(size_t(len), '\0');
    if (!in.read(name.data(), len) || in.get() != '\n') return std::nullopt;
    out.push_back(std::move(name));
  }
  if (in.peek() != std::char_traits<char>::eof()) return std::nullopt;
  return out;
}

std::string write_cached_node_names(const std::string& dir, const std::string& key,
                                    const std::vector<std::string>& names) {
  std::string body = std::to_string(names.size()) + '\n';
  for (const std::string& n : names) body += std::to_string(n.size()) + '\n' + n + '\n';
  return write_cache_entry(dir, kNodeNamesCache, key, body);
}

}  // namespace pd
