// Length units of scenes and mesh files.
#pragma once

#include <optional>
#include <string>

namespace pd {

/// Millimetres per unit for "mm", "cm", "m", "in", "ft"; nothing for others.
std::optional<double> unit_in_mm(const std::string& unit);
inline constexpr const char* kUnitNames = "mm, cm, m, in, ft";

/// The unit a mesh file's format fixes, by its extension: "m" for glTF 2.0
/// (.gltf, .glb; the specification's unit is the metre), else nothing (the
/// file takes its part's or scene's unit).
std::optional<std::string> format_unit(const std::string& mesh_path);

/// Scene units per unit of a mesh part without a `units` key: its format's
/// unit (format_unit) over the scene's, else 1.
double mesh_to_scene_units(const std::string& mesh_path, const std::string& scene_unit);

}  // namespace pd
