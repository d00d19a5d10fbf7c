#include "cache_file.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string_view>

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
    // The whole file in one read (not a character at a time: a cached run
    // reads an entry or two per mesh file), then its three lines.
    std::ifstream in(entry_path(dir, kind, key), std::ios::binary | std::ios::ate);
    if (!in) return std::nullopt;
    const std::streamoff size = in.tellg();
    if (size < 0) return std::nullopt;
    std::string e(static_cast<size_t>(size), '\0');
    if (!in.seekg(0) || !in.read(e.data(), size)) return std::nullopt;
    size_t at = 0;
    const auto line = [&](std::string_view& out) {
      const size_t eol = e.find('\n', at);
      if (eol == std::string::npos) return false;
      out = std::string_view(e).substr(at, eol - at);
      at = eol + 1;
      return true;
    };
    std::string_view format, stored_key, checksum;
    if (!line(format) || format != kind.format) return std::nullopt;
    if (!line(stored_key) || stored_key != key) return std::nullopt;
    if (!line(checksum)) return std::nullopt;
    if (content_hash(std::string_view(e).substr(at)) != checksum) return std::nullopt;
    e.erase(0, at);
    return e;
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
