// Cached tessellation sags (geometry/tessellation_sag.h): a mesh file's
// measurement stored per file content, so a rerun under `tolerance: auto`
// measures nothing and, for parts that keep no surface, reads no file.
// Checked cache files (cache_file.h): an entry that does not read back whole is
// measured again.
#pragma once

#include <optional>
#include <string>

#include "geometry/tessellation_sag.h"

namespace pd {

/// The key of a file's measurement: its content hash, whether each of its
/// meshes is a piece of its own (they are measured one by one either way, but
/// the loader reads them differently) and the format version.
std::string sag_key(const std::string& content_hash, bool per_mesh);

std::optional<TessellationSag> read_cached_sag(const std::string& dir, const std::string& key);

/// Stores the entry (creating `dir`); "" or why it could not.
std::string write_cached_sag(const std::string& dir, const std::string& key,
                             const TessellationSag& s);

}  // namespace pd
