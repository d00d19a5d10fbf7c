#include "scene/units.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace pd {

std::optional<double> unit_in_mm(const std::string& unit) {
  if (unit == "mm") return 1.0;
  if (unit == "cm") return 10.0;
  if (unit == "m") return 1000.0;
  if (unit == "in") return 25.4;
  if (unit == "ft") return 304.8;
  return std::nullopt;
}

std::optional<std::string> format_unit(const std::string& mesh_path) {
  std::string ext = std::filesystem::path(mesh_path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".gltf" || ext == ".glb") return "m";
  return std::nullopt;
}

double mesh_to_scene_units(const std::string& mesh_path, const std::string& scene_unit) {
  const std::optional<std::string> u = format_unit(mesh_path);
  const std::optional<double> scene = unit_in_mm(scene_unit);
  return u && scene ? *unit_in_mm(*u) / *scene : 1.0;
}

}  // namespace pd
