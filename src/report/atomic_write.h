// Writing an output file whole or not at all.
#pragma once

#include <string>

namespace pd {

/// Writes `content` to a temporary file beside `path`, then renames it over
/// `path`: a reader never sees half a report. Throws std::runtime_error.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace pd
