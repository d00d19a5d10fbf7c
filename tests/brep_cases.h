// B-rep test cases made with a CAD kernel (Open CASCADE's primitives and
// Booleans, BRepPrimAPI and BRepAlgoAPI) and written as STEP the way
// exporters write them (STEPCAFControl_Writer: an assembly of named products
// placed by instance locations). Compiled into the tests only; the product's
// Open CASCADE code is in src/brep.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "geometry/types.h"

namespace pd_test {
using pd::Points;
using pd::Vec3;
}  // namespace pd_test

namespace pd_test {

/// A solid from primitives (lengths in mm).
struct BrepSolid {
  enum class Kind {
    kBox,              ///< p: dx, dy, dz (a corner at the origin)
    kCylinder,         ///< p: radius, height (axis z from the origin)
    kTorus,            ///< p: major, minor radius (axis z about the origin)
    kSphere,           ///< p: radius
    kPlateWithHole,    ///< p: dx, dy, dz, hole radius (a z hole through its middle)
    kShaftWithGroove,  ///< p: radius, height, groove minor radius, groove z (torus cut)
    kTwoBoxes,         ///< p: dx, dy, dz: two boxes face to face along x, one product
    kBoxShell,         ///< p: dx, dy, dz: a box's faces without a solid (a surface model)
    kTilted,           ///< a kBox p rotated 30° about x then 20° about z (free-form free)
  };
  Kind kind = Kind::kBox;
  std::array<double, 4> p{};
};

struct BrepCasePart {
  std::string name;
  BrepSolid solid;
  Vec3 at = Vec3::Zero();     ///< the instance's translation (mm)
  Vec3 axis = Vec3::UnitZ();  ///< its rotation's axis
  double angle = 0.0;         ///< and angle (radians)
};

/// Writes `parts` as one STEP assembly (one product per part, named, placed by
/// its instance location), its lengths in `unit` ("mm" or "in").
void write_step_assembly(const std::string& path, const std::vector<BrepCasePart>& parts,
                         const std::string& unit = "mm");

/// Writes one part as a STEP part file (its product only, placed).
void write_step_part(const std::string& path, const BrepCasePart& part,
                     const std::string& unit = "mm");

/// Writes one part's shape, placed, as an Open CASCADE .brep file.
void write_brep_part(const std::string& path, const BrepCasePart& part);

/// Points on the faces of each leaf instance of a B-rep file (in the order
/// pdcheck numbers its leaves), placed as pdcheck places them, in mm: an
/// n × n grid over each face's parameter box, kept where it lies on the face.
std::vector<Points> leaf_face_samples(const std::string& path, int n);

}  // namespace pd_test
