// Cached convexity measurements: a mesh file's measured nonconvexity
// (geometry/convexity.h) stored per (file content, concavity tolerance), so a
// rerun on unchanged parts measures nothing. Checked cache files
// (cache_file.h): an entry that does not read back whole is measured again.
#pragma once

#include <optional>
#include <string>

namespace pd {

/// What the parts stage keeps of a measurement (file units).
struct StoredConvexity {
  double concavity = 0.0;  ///< the estimated concavity (a lower bound when above the threshold)
  bool closed = false;     ///< the mesh bounds a solid
};

/// The key of a file's measurement: its content hash, the concavity tolerance
/// and the threshold its estimate stops above (file units, exact bits), the
/// sampling density and the format version.
std::string convexity_key(const std::string& content_hash, double concavity_tol, double stop_above);

std::optional<StoredConvexity> read_cached_convexity(const std::string& dir,
                                                     const std::string& key);

/// Stores the entry (creating `dir`); "" or why it could not.
std::string write_cached_convexity(const std::string& dir, const std::string& key,
                                   const StoredConvexity& c);

}  // namespace pd
