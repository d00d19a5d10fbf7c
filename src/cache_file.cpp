#include "cache_file.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "atomic_write.h"
#include "hash.h"

namespace pd {

namespace {

std::string entry_path(const std::string& dir, const CacheKind& kind, const std::string& key) {
  return (std::filesystem::path(dir) / (key + kind.extension)).string();
}

}  // namespace

std::string default_cache_dir() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg && *xdg) return (std::filesystem::path(xdg) / "pdcheck").string();
  const char* home = std::getenv("HOME");
  if (home && *home) return (std::filesystem::path(home) / ".cache" / "pdcheck").string();
  return "";
}

// Layout: format line, key line, checksum line (the body's content hash), body.
std::optional<std::string> read_cache_entry(const std::string& dir, const CacheKind& kind,
                                            const std::string& key) {
  if (dir.empty()) return std::nullopt;
  try {
    std::ifstream in(entry_path(dir, kind, key), std::ios::binary);
    if (!in) return std::nullopt;
    std::string format, stored_key, checksum;
    if (!std::getline(in, format) || format != kind.format) return std::nullopt;
    if (!std::getline(in, stored_key) || stored_key != key) return std::nullopt;
    if (!std::getline(in, checksum)) return std::nullopt;
    std::string body{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad() || content_hash(body) != checksum) return std::nullopt;
    return body;
  } catch (const std::exception&) {  // e.g. a directory where the entry should be
    return std::nullopt;
  }
}

std::string write_cache_entry(const std::string& dir, const CacheKind& kind, const std::string& key,
                              const std::string& body) {
  if (dir.empty()) return "";
  try {
    std::filesystem::create_directories(dir);
    // Unsynced: an entry a crash cut short fails its checksum and is a miss.
    write_file_atomically(
        entry_path(dir, kind, key),
        std::string(kind.format) + "\n" + key + "\n" + content_hash(body) + "\n" + body,
        /*sync=*/false);
  } catch (const std::exception& e) {
    return std::string("cache ") + dir + ": " + e.what();
  }
  return "";
}

}  // namespace pd
