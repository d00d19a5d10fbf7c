#include "scene/node_names.h"

#include <map>

namespace pd {

std::string escape_node_name(std::string_view name) {
  std::string out;
  out.reserve(name.size());
  for (const char c : name) {
    if (c == '%')
      out += "%25";
    else if (c == '/')
      out += "%2F";
    else if (c == '#')
      out += "%23";
    else
      out += c;
  }
  return out;
}

std::vector<std::string> sibling_segments(const std::vector<std::string>& names) {
  std::vector<std::string> out;
  out.reserve(names.size());
  std::map<std::string, int> seen;
  for (size_t k = 0; k < names.size(); ++k) {
    std::string s = names[k].empty() ? "node" + std::to_string(k) : escape_node_name(names[k]);
    // A suffix cannot meet a plain name: '#' in a name is escaped above
    // ("a", "a", "a#2" give "a", "a#2", "a%232").
    const int n = ++seen[s];
    if (n > 1) s += "#" + std::to_string(n);
    out.push_back(std::move(s));
  }
  return out;
}

std::string node_part_id(const std::string& part_id, const std::string& node_path) {
  return part_id + "/" + node_path;
}

std::string node_part_group(const std::string& part_group, const std::string& node_path) {
  const auto slash = node_path.rfind('/');
  const std::string parent = slash == std::string::npos ? "" : node_path.substr(0, slash);
  if (part_group.empty()) return parent;
  if (parent.empty()) return part_group;
  return part_group + "/" + parent;
}

}  // namespace pd
