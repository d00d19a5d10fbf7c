// The JSON data an HTML report carries (between its data script tags), for tests.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace pd {

inline nlohmann::json page_data(const std::string& page) {
  const std::string open = "<script id=\"pdcheck-data\" type=\"application/json\">";
  const size_t at = page.find(open);
  if (at == std::string::npos) return nullptr;
  const size_t end = page.find("</script>", at);
  return nlohmann::json::parse(page.substr(at + open.size(), end - at - open.size()));
}

/// Base64 decoded, as the page decodes its meshes' vertex data.
inline std::string unbase64(const std::string& in) {
  const std::string abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  unsigned bits = 0;
  int n = 0;
  for (char c : in) {
    if (c == '=') break;
    bits = (bits << 6) | static_cast<unsigned>(abc.find(c));
    if ((n += 6) >= 8) out += static_cast<char>((bits >> (n -= 8)) & 0xff);
  }
  return out;
}

}  // namespace pd
