#include "scene/units.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
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

std::optional<LengthArg> parse_length(const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  if (end == begin || errno == ERANGE || !std::isfinite(v)) return std::nullopt;
  std::string rest(end);
  rest.erase(0, rest.find_first_not_of(' '));
  LengthArg out{v, std::nullopt};
  if (rest.empty()) return out;
  if (!unit_in_mm(rest)) return std::nullopt;
  out.unit = rest;
  return out;
}

double length_in(const LengthArg& length, const std::string& scene_unit) {
  if (!length.unit || *length.unit == scene_unit) return length.value;
  return length.value * *unit_in_mm(*length.unit) / *unit_in_mm(scene_unit);
}

std::optional<std::string> format_unit(const std::string& mesh_path) {
  std::string ext = std::filesystem::path(mesh_path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".gltf" || ext == ".glb") return "m";
  if (ext == ".step" || ext == ".stp") return "mm";  // the reader converts the file's unit to mm
  return std::nullopt;
}

double mesh_to_scene_units(const std::string& mesh_path, const std::string& scene_unit) {
  const std::optional<std::string> u = format_unit(mesh_path);
  const std::optional<double> scene = unit_in_mm(scene_unit);
  return u && scene ? *unit_in_mm(*u) / *scene : 1.0;
}

}  // namespace pd
