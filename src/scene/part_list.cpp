#include <cctype>
#include <filesystem>
#include <sstream>
#include <system_error>
#include <vector>

#include "brep/brep_file.h"
#include "scene/scene.h"
#include "scene/units.h"

namespace pd {

namespace fs = std::filesystem;

std::string part_list_id(const std::string& path) {
  fs::path p = fs::path(path).lexically_normal();
  if (p.is_absolute()) {
    std::error_code ec;
    const fs::path cwd = fs::current_path(ec).lexically_normal();
    if (!ec) {
      const fs::path rel = p.lexically_relative(cwd);
      if (!rel.empty() && *rel.begin() != ".." && rel != ".") p = rel;
    }
  }
  std::string id = p.string();
  return id.empty() ? path : id;
}

SceneSpec parse_part_list(const std::string& text, const std::string& path) {
  SceneSpec s;
  s.path = path;
  s.part_list = true;
  std::istringstream in(text);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    PartSpec p;
    const auto tab = line.find('\t');
    if (tab == std::string::npos) {
      p.id = part_list_id(line);
      p.mesh = line;
    } else {
      // id<TAB>path, optionally <TAB>group and <TAB>tags (comma-separated).
      std::vector<std::string> fields;
      for (size_t b = 0, e = 0; e != std::string::npos; b = e + 1) {
        e = line.find('\t', b);
        fields.push_back(line.substr(b, e == std::string::npos ? e : e - b));
      }
      if (fields.size() > 4)
        throw SceneError(path + ": line " + std::to_string(n) +
                         ": expected at most 4 fields: id, path, group, tags");
      p.id = fields[0];
      p.mesh = fields[1];
      if (fields.size() > 2) p.group = fields[2];
      if (fields.size() > 3)
        for (size_t b = 0, e = 0; e != std::string::npos; b = e + 1) {
          e = fields[3].find(',', b);
          const std::string tag = fields[3].substr(b, e == std::string::npos ? e : e - b);
          if (!tag.empty()) p.tags.push_back(tag);
        }
    }
    p.where = path + ": line " + std::to_string(n) + " (\"" + p.id + "\")";
    p.split_nodes = p.split_auto = is_brep_path(*p.mesh);  // an assembly: a part per leaf
    if (p.id.empty() || p.mesh->empty())
      throw SceneError(path + ": line " + std::to_string(n) +
                       ": expected \"path\" or \"id<TAB>path\"");
    s.parts.push_back(std::move(p));
  }
  validate_scene(s);
  return s;
}

bool looks_like_mesh_file(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  for (const char* m :
       {".stl", ".obj", ".ply", ".gltf", ".glb", ".3mf", ".off", ".fbx", ".dae", ".3ds"})
    if (ext == m) return true;
  return is_brep_path(path);
}

std::optional<std::string> empty_scene_problem(const SceneSpec& s) {
  if (s.pairs && s.pairs->empty())
    return s.path +
           ": pairs: an empty list: no pair to check (leave \"pairs\" out to check every pair "
           "whose boxes meet; --allow-empty accepts an empty input)";
  if (!s.parts.empty()) return std::nullopt;
  const std::string what = s.part_list ? "an empty part list (no mesh path on any line)"
                                       : "no parts (\"parts\" is empty)";
  return s.path + ": " + what + ": nothing to check (--allow-empty accepts an empty input)";
}

SceneSpec parse_stdin_scene(const std::string& text, const std::optional<std::string>& units,
                            int threads) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && text[first] == '{')
    return parse_scene_json(text, "<stdin>", "", units, threads);
  SceneSpec s = parse_part_list(text, "<stdin>");
  s.units = units;
  for (PartSpec& p : s.parts) p.to_scene_units = mesh_to_scene_units(*p.mesh, units.value_or("mm"));
  return s;
}

}  // namespace pd
