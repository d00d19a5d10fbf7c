// Cached node paths of split files (scene/split_nodes.h): a file's node paths
// stored per file content, so a rerun splits it without parsing it (the split
// otherwise reads each split file once more than its parts need). Checked
// cache files (cache_file.h): an entry that does not read back whole is a miss.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace pd {

/// The key of a file's node paths: its content hash and the format version.
std::string node_names_key(const std::string& content_hash);

std::optional<std::vector<std::string>> read_cached_node_names(const std::string& dir,
                                                               const std::string& key);

/// Stores the entry (creating `dir`); "" or why it could not.
std::string write_cached_node_names(const std::string& dir, const std::string& key,
                                    const std::vector<std::string>& names);

}  // namespace pd
