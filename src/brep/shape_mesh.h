// A shape's solids as one welded triangle mesh with the error it carries
// (internal to src/brep: names Open CASCADE types).
#pragma once

#include <TopoDS_Shape.hxx>

#include "brep/brep_file.h"

namespace pd {

struct ShapeMesh {
  Mesh mesh;  ///< the solids' faces, in the shape's coordinates
  Tessellation tessellation;
  int solids = 0;
  long open_edges = 0;                ///< mesh edges used by an odd number of triangles
  std::vector<double> triangle_sags;  ///< per triangle of `mesh`: its face's sag
};

/// Meshes the solids of `shape` at linear deflection `deflection` (angular
/// deflection kMeshAngle) after removing any mesh the shape carried, so the
/// result depends on the shape and the deflection alone. Vertices are welded
/// by topology: the points of an edge's polygon, and of a vertex, are one mesh
/// vertex for every face that shares them (a seam's two sides included), so
/// the solid's mesh is closed where the solid is. Faces outside solids (free
/// shells and faces) are left out. Each face's sag is face_sag's. A deflection
/// of 0 meshes nothing: the solids are counted. `in_parallel`: the mesher
/// meshes the faces on Open CASCADE's thread pool (the same meshes: each face
/// is meshed alone, after its edges).
ShapeMesh mesh_solids(const TopoDS_Shape& shape, double deflection, bool in_parallel = false);

}  // namespace pd
