#include "scene/glb_check.h"

namespace pd {

namespace {

uint32_t u32(const std::string& b, size_t at) {  // little-endian, as GLB stores it
  return uint32_t(uint8_t(b[at])) | uint32_t(uint8_t(b[at + 1])) << 8 |
         uint32_t(uint8_t(b[at + 2])) << 16 | uint32_t(uint8_t(b[at + 3])) << 24;
}

constexpr uint32_t kJson = 0x4E4F534A;  // "JSON"

}  // namespace

bool looks_like_glb(std::string_view bytes) {
  return bytes.substr(0, 4) == "glTF";
}

std::string glb_problem(const std::function<std::string(uint64_t, size_t)>& at, uint64_t size) {
  const std::string head = at(0, 20);
  if (head.size() < 12) return "binary glTF cut short: " + std::to_string(size) + " bytes";
  const uint32_t version = u32(head, 4), length = u32(head, 8);
  const std::string declares = "the binary glTF header declares ";
  if (length > size)
    return declares + std::to_string(length) + " bytes, the file has " + std::to_string(size);
  if (version == 1) {  // header of 20 bytes, then the content (JSON) and the body
    if (head.size() < 20) return "binary glTF (version 1) cut short in its header";
    const uint64_t content = u32(head, 12);
    if (20 + content > length)
      return declares + "content of " + std::to_string(content) + " bytes in a file of " +
             std::to_string(length);
    return "";
  }
  if (version != 2) return "binary glTF of version " + std::to_string(version) + " (1 or 2 read)";
  uint64_t offset = 12;
  for (int chunk = 0; offset < length; ++chunk) {
    const std::string ch = at(offset, 8);
    if (ch.size() < 8 || offset + 8 > length)
      return "binary glTF cut short in the header of chunk " + std::to_string(chunk);
    const uint64_t bytes = u32(ch, 0);
    if (offset + 8 + bytes > length)
      return "binary glTF chunk " + std::to_string(chunk) + " declares " + std::to_string(bytes) +
             " bytes, " + std::to_string(length - offset - 8) + " are left";
    if (chunk == 0 && u32(ch, 4) != kJson) return "binary glTF whose first chunk is not JSON";
    offset += 8 + bytes;
  }
  return "";
}

}  // namespace pd
