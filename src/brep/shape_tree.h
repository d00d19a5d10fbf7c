// A B-rep file's assembly tree with its products' shapes (internal to
// src/brep: names Open CASCADE types). Read once, it serves the meshes
// (brep_file.cpp) and the exact solids (exact_pair.cpp) alike, so both number
// the leaf instances the same way.
#pragma once

#include <TopoDS_Shape.hxx>
#include <gp_Trsf.hxx>
#include <string>
#include <vector>

#include "brep/brep_file.h"

namespace pd {

struct ShapeTree {
  struct Leaf {
    TopoDS_Shape product;     ///< the product's shape, unplaced (shared by its instances)
    std::string product_key;  ///< the same for every instance of one product
    gp_Trsf place;            ///< the assembly's placement of this instance (file units)
    std::string name_path;    ///< the names from the root, for messages
  };
  std::vector<BrepNode> nodes;  ///< depth first, in file order; leaves index `leaves`
  std::vector<Leaf> leaves;
  std::string unit;  ///< "mm" for STEP (converted on reading), "" for .brep
};

/// Reads a STEP (into an XCAF document, lengths in mm) or .brep file. Throws
/// std::runtime_error naming what failed (the caller names the file).
/// Open CASCADE's messages go nowhere (never to stdout).
ShapeTree read_shape_tree(const std::string& path);

}  // namespace pd
