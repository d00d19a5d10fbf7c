// Length units of scenes and mesh files.
#pragma once

#include <optional>
#include <string>

namespace pd {

/// Millimetres per unit for "mm", "cm", "m", "in", "ft"; nothing for others.
std::optional<double> unit_in_mm(const std::string& unit);
inline constexpr const char* kUnitNames = "mm, cm, m, in, ft";

/// A length as the command line gives it: a number, optionally followed by a
/// unit ("0.05mm", "2in", "0.1 cm"); without one it is in the scene's unit.
struct LengthArg {
  double value = 0.0;
  std::optional<std::string> unit;
};

/// Parses a LengthArg; nullopt when `text` is not a finite number followed by
/// nothing, spaces, or one of kUnitNames.
std::optional<LengthArg> parse_length(const std::string& text);

/// The length in `scene_unit` (its own unit converted; none: as it is).
double length_in(const LengthArg& length, const std::string& scene_unit);

/// The unit a mesh file's format fixes, by its extension: "m" for glTF 2.0
/// (.gltf, .glb; the specification's unit is the metre), "mm" for STEP (.step,
/// .stp: the file declares its unit and the reader converts it to mm), else
/// nothing (the file takes its part's or scene's unit).
std::optional<std::string> format_unit(const std::string& mesh_path);

/// Scene units per unit of a mesh part without a `units` key: its format's
/// unit (format_unit) over the scene's, else 1.
double mesh_to_scene_units(const std::string& mesh_path, const std::string& scene_unit);

}  // namespace pd
