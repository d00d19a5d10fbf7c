// Length units of scenes and mesh files.
#pragma once

#include <optional>
#include <string>

namespace pd {

/// Millimetres per unit for "mm", "cm", "m", "in", "ft"; nothing for others.
std::optional<double> unit_in_mm(const std::string& unit);
inline constexpr const char* kUnitNames = "mm, cm, m, in, ft";

}  // namespace pd
