#include "batch/decomposition_cache.h"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "atomic_write.h"
#include "hash.h"
#include "tolerances.h"

namespace pd {

namespace {

// 2: reflex-edge cuts and the work budget (entries of the old algorithm are
// not reused: they may hold its incomplete decompositions).
constexpr const char* kFormat = "pdcheck-decomposition-2";

std::string entry_path(const std::string& dir, const std::string& key) {
  return (std::filesystem::path(dir) / (key + ".pdd")).string();
}

// Lossless and compact: the doubles as their bytes.
std::string piece_bytes(const std::vector<Points>& pieces) {
  std::string out;
  for (const Points& p : pieces) {
    const long n = p.cols();
    out.append(reinterpret_cast<const char*>(&n), sizeof n);
    out.append(reinterpret_cast<const char*>(p.data()), sizeof(double) * 3 * n);
  }
  return out;
}

}  // namespace

std::string default_cache_dir() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg && *xdg) return (std::filesystem::path(xdg) / "pdcheck").string();
  const char* home = std::getenv("HOME");
  if (home && *home) return (std::filesystem::path(home) / ".cache" / "pdcheck").string();
  return "";
}

std::string decomposition_key(const std::string& content_hash, double concavity_tol,
                              double time_limit_seconds) {
  Hasher h;
  h.add(kFormat).add(content_hash).add(concavity_tol).add(time_limit_seconds);
  h.add(static_cast<double>(tol::kDecomposeMaxWork));
  return h.hex();
}

// Layout: format line, key line, "complete seconds count" line, note line,
// checksum line, then the piece bytes (count, then 3·count doubles, per piece).
std::optional<StoredDecomposition> read_cached_decomposition(const std::string& dir,
                                                             const std::string& key) {
  if (dir.empty()) return std::nullopt;
  std::ifstream in(entry_path(dir, key), std::ios::binary);
  if (!in) return std::nullopt;
  std::string format, stored_key, header, note, checksum;
  if (!std::getline(in, format) || format != kFormat) return std::nullopt;
  if (!std::getline(in, stored_key) || stored_key != key) return std::nullopt;
  if (!std::getline(in, header) || !std::getline(in, note) || !std::getline(in, checksum))
    return std::nullopt;
  const std::string body{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (content_hash(body) != checksum) return std::nullopt;
  StoredDecomposition d;
  long count = 0;
  int complete = 0;
  std::istringstream hs(header);
  if (!(hs >> complete >> d.seconds >> count) || count < 0) return std::nullopt;
  d.complete = complete != 0;
  d.note = note;
  size_t off = 0;
  for (long k = 0; k < count; ++k) {
    long n = 0;
    if (off + sizeof n > body.size()) return std::nullopt;
    std::memcpy(&n, body.data() + off, sizeof n);
    off += sizeof n;
    if (n < 0 || off + sizeof(double) * 3 * static_cast<size_t>(n) > body.size())
      return std::nullopt;
    Points p(3, n);
    std::memcpy(p.data(), body.data() + off, sizeof(double) * 3 * n);
    off += sizeof(double) * 3 * n;
    d.pieces.push_back(std::move(p));
  }
  if (off != body.size()) return std::nullopt;
  return d;
}

std::string write_cached_decomposition(const std::string& dir, const std::string& key,
                                       const StoredDecomposition& d) {
  if (dir.empty()) return "";
  try {
    std::filesystem::create_directories(dir);
    const std::string body = piece_bytes(d.pieces);
    std::string note = d.note;
    for (char& c : note)
      if (c == '\n') c = ' ';
    std::ostringstream head;
    head.precision(17);
    head << kFormat << "\n"
         << key << "\n"
         << (d.complete ? 1 : 0) << " " << d.seconds << " " << d.pieces.size() << "\n"
         << note << "\n"
         << content_hash(body) << "\n";
    write_file_atomically(entry_path(dir, key), head.str() + body);
  } catch (const std::exception& e) {
    return std::string("decomposition cache ") + dir + ": " + e.what();
  }
  return "";
}

}  // namespace pd
