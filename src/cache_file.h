// Checked cache entries: one file per key in a cache directory, shared by runs
// that may write it at the same time (the decomposition, refinement and
// convexity caches). An entry is written to a temporary file and renamed into
// place, so a reader never sees half of one; it reads back only when its
// format, key and body checksum all match, so a truncated, edited or foreign
// file is a miss (recomputed), never an error.
#pragma once

#include <optional>
#include <string>

namespace pd {

/// What kind of entry a file holds: its format line (bump it when the body's
/// layout or meaning changes: old entries then miss) and its file extension.
struct CacheKind {
  const char* format;
  const char* extension;  ///< with the dot: ".pdd"
};

/// $XDG_CACHE_HOME/pdcheck, else $HOME/.cache/pdcheck, else "" (no cache).
std::string default_cache_dir();

/// The body stored under `key` in `dir`, or nullopt when `dir` is "", the
/// entry is absent or unreadable, or it is not whole and of this kind and key.
std::optional<std::string> read_cache_entry(const std::string& dir, const CacheKind& kind,
                                            const std::string& key);

/// Whether a file stands under `key` in `dir` (its content unchecked: it may
/// still read back as a miss).
bool cache_entry_present(const std::string& dir, const CacheKind& kind, const std::string& key);

/// Stores `body` under `key` (creating `dir`); "" or why it could not (the run
/// goes on without the cache). Nothing is written when `dir` is "".
std::string write_cache_entry(const std::string& dir, const CacheKind& kind, const std::string& key,
                              const std::string& body);

}  // namespace pd
