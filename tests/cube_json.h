// A unit-free axis-aligned cube as a scene's inline part: the CLI and batch
// suites' simplest part.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace pd_test {

/// The part `id`: a cube of side s with its lowest corner at (x, y, z).
inline nlohmann::json cube_json(const std::string& id, double x, double y = 0, double z = 0,
                                double s = 1) {
  nlohmann::json v = nlohmann::json::array();
  for (int k = 0; k < 8; ++k)
    v.push_back({x + s * (k & 1), y + s * ((k >> 1) & 1), z + s * ((k >> 2) & 1)});
  return {{"id", id}, {"vertices", v}};
}

}  // namespace pd_test
