// B-rep files through Open CASCADE: STEP assemblies and parts (AP203, AP214,
// AP242 B-rep) and OCCT's own .brep, read into leaf instances, each meshed
// with a known deflection and the chord error that mesh carries
// (docs/scene-format.md "STEP and B-rep files", docs/solver.md "B-rep parts").
//
// Every Open CASCADE call of pdcheck lives in src/brep: its headers name no
// OCCT type, and no other layer includes OCCT (scripts/check_layers.py).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/mesh.h"

namespace pd {

/// Whether `path` names a B-rep file by its extension (.step, .stp, .brep;
/// any case).
bool is_brep_path(const std::string& path);

/// What the distance between a tessellation and its faces rests on:
/// kBound: computed from the triangles and the exact surfaces (planes and
/// analytic surfaces: cylinders, cones, spheres, tori, and their lines,
/// circles and ellipses), an upper bound; kEstimate: sampled on at least one
/// free-form face or edge (B-splines and the like), not a bound.
enum class SagBasis { kBound, kEstimate };
const char* sag_basis_name(SagBasis b);

/// A mesh made from exact faces and how far it may be from them.
struct Tessellation {
  double deflection = 0.0;  ///< the linear deflection asked of the mesher (file units)
  /// The largest distance between a point of a face and the mesh, either way
  /// (file units): a bound or an estimate as `basis` says.
  double sag = 0.0;
  SagBasis basis = SagBasis::kBound;
  long faces = 0;          ///< faces meshed
  long free_form = 0;      ///< of them, faces whose sag is only estimated
  double tolerance = 0.0;  ///< the largest tolerance of the shape's faces, edges and vertices
};

/// The larger sag of two tessellations, and their weaker basis.
Tessellation combine(const Tessellation& a, const Tessellation& b);

/// A node of a B-rep file's assembly tree, in depth-first file order.
struct BrepNode {
  std::string name;  ///< the instance's name, else its product's ("" when neither has one)
  int parent = -1;   ///< index in BrepFile::nodes; -1 for a root (a free shape of the file)
  int leaf = -1;     ///< index in BrepFile::leaves, for a node without components
};

/// A leaf instance: a product placed in the file's assembly.
struct BrepLeaf {
  Mesh mesh;  ///< its faces' triangles, placed by the assembly (file units, welded shells)
  Tessellation tessellation;
  /// Per triangle of `mesh`: the sag of the face it was made for (file units,
  /// rounded up to float): where on the part its sag is.
  std::vector<float> triangle_sags;
  int solids = 0;  ///< solids in the product's shape
  /// Why the leaf cannot be checked (no solid: a surface model), naming it.
  std::optional<std::string> error;
};

struct BrepFile {
  std::vector<BrepNode> nodes;
  std::vector<BrepLeaf> leaves;
  std::vector<std::string> warnings;  ///< what the reader reported, naming the file
  /// STEP: "mm" (the file's own unit is converted by the reader); .brep: ""
  /// (the format has no unit: the part's units apply).
  std::string unit;
};

/// What B-rep meshes and their sags depend on besides the file and the
/// deflection: the sag bound's version (raised whenever the bound or the
/// meshing changes) and Open CASCADE's. Cache entries of B-rep meshes name it,
/// so that an upgrade misses them.
std::string brep_mesh_version();

/// Reads the B-rep file at `path` and meshes every product once at linear
/// deflection `deflection` (file units; the unit a STEP file is converted to,
/// mm). Throws std::runtime_error naming the file when it cannot be read or
/// holds no shape. Open CASCADE's messages go nowhere (never to stdout).
/// `threads` > 1 meshes distinct products, and each product's faces, side by
/// side on at most that many threads (the same meshes: each product and face
/// is meshed alone), unless two products share a face.
BrepFile read_brep_file(const std::string& path, double deflection, int threads = 1);

}  // namespace pd
