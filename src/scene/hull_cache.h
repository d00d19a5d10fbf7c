// Cached file hulls: each mesh of a file reduced to the vertices of its convex
// hull (file coordinates), stored per file content, so a rerun, or another
// shard on the same machine, hulls nothing it has hulled before and, where the
// part keeps no surface (pieces "hull" or "meshes"), does not read the file at
// all. Under `tolerance: auto` the entry also holds the file's tessellation
// sag (geometry/tessellation_sag.h), so a rerun reads one entry per file for
// both. Checked cache files (cache_file.h): an entry that does not read back
// whole is computed again.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/hull.h"
#include "geometry/tessellation_sag.h"
#include "geometry/types.h"

namespace pd {

/// What the parts stage keeps of a mesh file before placing it.
struct StoredHulls {
  std::vector<long> counts;           ///< vertices per mesh as read
  std::vector<Points> reduced;        ///< per mesh: its hull's vertices, file coordinates
  std::vector<std::string> warnings;  ///< the loader's about the file (one line each)
  /// The file's sag (file units), when a run under `tolerance: auto` measured
  /// it; a run without auto stores none, and a later auto run that finds none
  /// measures it and stores the entry again with it.
  std::optional<TessellationSag> sag;
};

/// The key of a file's hulls (and sag): its content hash, whether each mesh of
/// the file is its own piece (pieces "meshes") and the format version.
std::string hulls_key(const std::string& content_hash, bool per_mesh);

/// The entry's body as bytes (also what a loader process hands back of a
/// file it hulled), and back: nullopt when the bytes are not a whole entry.
std::string stored_hulls_bytes(const StoredHulls& h);
std::optional<StoredHulls> stored_hulls_from_bytes(const std::string& bytes);

std::optional<StoredHulls> read_cached_hulls(const std::string& dir, const std::string& key);

/// Stores the entry (creating `dir`); "" or why it could not.
std::string write_cached_hulls(const std::string& dir, const std::string& key,
                               const StoredHulls& h);

/// An inline part's hull (placed, scene units), keyed by its list's digest
/// (vertex_digest) and its placement: a rerun, or another shard on the
/// machine, hulls no unchanged inline part again. `.pdi` entries.
std::string inline_hull_key(const std::string& digest, double to_scene_units,
                            const Mat4& transform);

std::optional<Hull> read_cached_hull(const std::string& dir, const std::string& key);

/// Stores the entry (creating `dir`); "" or why it could not.
std::string write_cached_hull(const std::string& dir, const std::string& key, const Hull& h);

}  // namespace pd
