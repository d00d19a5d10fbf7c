// Cached convex decompositions: one entry per (mesh content, settings), so a
// nightly rerun on unchanged parts decomposes nothing. Entries are checked
// cache files (cache_file.h): one that does not read back whole is recomputed.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cache_file.h"
#include "geometry/types.h"

namespace pd {

/// A decomposition of one mesh file, in the file's own coordinates.
struct StoredDecomposition {
  std::vector<Points> pieces;  ///< each piece's vertices (its hull is the piece)
  bool complete = true;        ///< false: the time box ran out, pieces are a fallback
  std::string note;            ///< why incomplete, or what the decomposer reports
  double seconds = 0.0;        ///< the time it took when computed
};

/// The cache key of a file's decomposition: its content hash and every setting
/// that changes the result (as exact bits), plus the format version.
std::string decomposition_key(const std::string& content_hash, double concavity_tol,
                              double time_limit_seconds);

/// The entry for `key` in `dir`, or nullopt when absent or unreadable.
std::optional<StoredDecomposition> read_cached_decomposition(const std::string& dir,
                                                             const std::string& key);

/// Stores the entry (creating `dir`); returns "" or why it could not (the run
/// goes on without the cache).
std::string write_cached_decomposition(const std::string& dir, const std::string& key,
                                       const StoredDecomposition& d);

}  // namespace pd
