#include <sstream>

#include "scene/scene.h"

namespace pd {

SceneSpec parse_part_list(const std::string& text, const std::string& path) {
  SceneSpec s;
  s.path = path;
  std::istringstream in(text);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    PartSpec p;
    const auto tab = line.find('\t');
    if (tab == std::string::npos) {
      p.id = line;
      p.mesh = line;
    } else {
      p.id = line.substr(0, tab);
      p.mesh = line.substr(tab + 1);
    }
    p.where = path + ": line " + std::to_string(n) + " (\"" + p.id + "\")";
    if (p.id.empty() || p.mesh->empty())
      throw SceneError(path + ": line " + std::to_string(n) +
                       ": expected \"path\" or \"id<TAB>path\"");
    s.parts.push_back(std::move(p));
  }
  validate_scene(s);
  return s;
}

SceneSpec parse_stdin_scene(const std::string& text, const std::optional<std::string>& units,
                            int threads) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && text[first] == '{')
    return parse_scene_json(text, "<stdin>", "", units, threads);
  SceneSpec s = parse_part_list(text, "<stdin>");
  s.units = units;
  return s;
}

}  // namespace pd
