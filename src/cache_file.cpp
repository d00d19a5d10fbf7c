#include "cache_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
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

bool cache_entry_present(const std::string& dir, const CacheKind& kind, const std::string& key) {
  struct stat st {};
  return !dir.empty() && ::stat(entry_path(dir, kind, key).c_str(), &st) == 0 &&
         S_ISREG(st.st_mode);
}

// Layout: format line, key line, checksum line (the body's content hash), body.
std::optional<std::string> read_cache_entry(const std::string& dir, const CacheKind& kind,
                                            const std::string& key) {
  if (dir.empty()) return std::nullopt;
  try {
    // The whole file in one read (not a character at a time: a cached run
    // reads an entry or two per mesh file), then its three lines. Only a
    // regular file is an entry: a directory or a FIFO (opened without
    // blocking) under its name is a miss.
    const int fd = ::open(entry_path(dir, kind, key).c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) return std::nullopt;
    struct Closer {
      int fd;
      ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
    std::string e(static_cast<size_t>(st.st_size), '\0');
    size_t got = 0;
    while (got < e.size()) {
      const ssize_t n = ::read(fd, e.data() + got, e.size() - got);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return std::nullopt;  // an error, or shorter than it said
      got += static_cast<size_t>(n);
    }
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
