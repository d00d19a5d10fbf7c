#include "file_hash.h"

#include <filesystem>
#include <fstream>

#include "hash.h"

namespace pd {

std::string file_content_hash(const std::string& path) {
  try {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return content_hash("not a file|" + path);
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) return content_hash("unreadable|" + path);
    const std::streamoff size = in.tellg();
    if (size < 0) return content_hash("unreadable|" + path);
    std::string bytes(static_cast<size_t>(size), '\0');
    in.seekg(0);
    if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())) ||
        in.peek() != std::char_traits<char>::eof())
      return content_hash("unreadable|" + path);  // shorter or longer than sized: changing
    return content_hash(bytes);
  } catch (const std::exception&) {
    return content_hash("unreadable|" + path);
  }
}

}  // namespace pd
