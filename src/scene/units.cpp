#include "scene/units.h"

namespace pd {

std::optional<double> unit_in_mm(const std::string& unit) {
  if (unit == "mm") return 1.0;
  if (unit == "cm") return 10.0;
  if (unit == "m") return 1000.0;
  if (unit == "in") return 25.4;
  if (unit == "ft") return 304.8;
  return std::nullopt;
}

}  // namespace pd
