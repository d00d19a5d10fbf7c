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

}  // namespace pd
