// Writing a regular file whole or not at all.
#pragma once

#include <string>

namespace pd {

/// Writes `content` to a new temporary file beside `path`, then renames it over
/// `path`: a reader never sees half a file, and a failed or interrupted write
/// leaves the old file as it was and no temporary file behind. `path` must name
/// a regular file or nothing (symlinks resolved by the caller: see
/// output_file.h). A new file gets mode 0666 less the umask; an existing one
/// keeps its mode (and, when run as root, its owner). `sync`: the content
/// reaches the disk before the rename (a report survives a crash whole); a
/// cache entry, checked on read, skips that wait. Throws OutputError.
void write_file_atomically(const std::string& path, const std::string& content, bool sync = true);

/// Writes all of `content` to `fd`, retrying short writes; false with errno set on failure.
bool write_all_fd(int fd, const std::string& content);

/// Creates a new file with a random name "<dir>/.<stem>.XXXXXX" (O_EXCL, mode
/// 0666 less the umask) and returns its descriptor, the name in `created`;
/// -1 with errno set on failure.
int create_temp_beside(const std::string& dir, const std::string& stem, std::string& created);

}  // namespace pd
