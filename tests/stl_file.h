// Writing a mesh as a binary STL file (float32 coordinates, as CAD exporters
// write them) for tests that run pdcheck on mesh files.
#pragma once

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include "geometry/mesh.h"

namespace pd::test {

inline void write_binary_stl(const std::string& path, const Mesh& m) {
  std::ofstream out(path, std::ios::binary);
  char header[80] = "pdcheck test mesh";
  out.write(header, sizeof header);
  const auto count = static_cast<std::uint32_t>(m.triangles.cols());
  out.write(reinterpret_cast<const char*>(&count), 4);
  for (long t = 0; t < m.triangles.cols(); ++t) {
    float f[12] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d)
        f[3 + 3 * k + d] = static_cast<float>(m.vertices(d, m.triangles(k, t)));
    out.write(reinterpret_cast<const char*>(f), sizeof f);
    const std::uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(&attributes), 2);
  }
}

}  // namespace pd::test
