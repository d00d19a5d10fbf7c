// Mesh files through assimp (STL, OBJ, PLY, glTF, …).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/types.h"

namespace pd {

/// A mesh file that cannot be used: unreadable, unknown format, no vertices.
class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The vertices of every mesh instance in a file, node transforms applied
/// (world = node · v, accumulated in double precision: assimp stores float32).
/// With split_instances, one point set per (node, mesh) instance; else one set.
std::vector<Points> load_mesh_vertices(const std::string& path, bool split_instances);

}  // namespace pd
