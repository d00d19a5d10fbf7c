// Mesh files through assimp (STL, OBJ, PLY, glTF, …).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/mesh.h"
#include "geometry/types.h"

namespace pd {

/// A mesh file that cannot be used: unreadable, unknown format, no vertices.
class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Every mesh instance in a file with its triangles, node transforms applied
/// (world = node · v, accumulated in double precision: assimp stores float32).
/// With split_instances, one mesh per (node, mesh) instance; else one mesh
/// (triangle indices offset to the concatenated vertices). Faces of more than
/// three vertices are fanned; points and lines contribute vertices only.
std::vector<Mesh> load_meshes(const std::string& path, bool split_instances);

/// The vertices of load_meshes, without triangles.
std::vector<Points> load_mesh_vertices(const std::string& path, bool split_instances);

}  // namespace pd
