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
    kChamferedSquare,  ///< p: half-width, height: a square block, axis z from the origin,
                       ///< chamfered by a cone (radius 1.5 → 1.05 half-widths): hyperbola edges
    kWavySlab,  ///< p: size, thickness: a non-rational B-spline face z = sin x cos y / 2 over
                ///< [0, size]², extruded by the thickness (B-spline and extrusion faces)
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

/// An exact reference for a pair of .brep files, from Open CASCADE alone (no
/// pdcheck code): the distance between their solids (BRepExtrema, solid by
/// solid) and the volume of their common part (BRepAlgoAPI_Common), and that
/// part's narrowest axis-aligned box extent (0 when empty).
struct ExactReference {
  double distance = 0.0;
  double common_volume = 0.0;
  double common_min_extent = 0.0;
};
ExactReference exact_reference(const std::string& brep_a, const std::string& brep_b);

}  // namespace pd_test
