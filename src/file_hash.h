// The content hash of a file (hash.h): the one reader of mesh files for
// hashing, used for --reuse, the shard manifest and the caches' keys.
#pragma once

#include <string>

namespace pd {

/// content_hash of the file's bytes. Only a regular file is read (a FIFO or a
/// device could block or never end; its load says why): anything else, or a
/// file that cannot be read, hashes its path and the reason, so it never
/// matches a readable file's hash.
std::string file_content_hash(const std::string& path);

}  // namespace pd
