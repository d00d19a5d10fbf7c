// How far a face's triangles lie from the face (internal to src/brep: names
// Open CASCADE types).
#pragma once

#include <Poly_Triangulation.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS_Face.hxx>

namespace pd {

/// The largest distance between a point of a face and its triangles, either
/// way: certified (`bound`) or sampled.
struct FaceSag {
  double value = 0.0;
  bool bound = true;
};

/// The chord error of the triangulation `t` (placed by `loc`) of `face`: for
/// every triangle, the distance between the surface over its parameter
/// triangle and the flat triangle (triangle_interpolation_bound with the
/// surface's second derivatives: bounds for planes, cylinders, cones, spheres,
/// tori, extrusions of lines, circles and splines, and non-rational B-spline
/// and Bézier surfaces (from the control nets of small pieces,
/// brep/spline_net.h); sampled at seven points of each triangle otherwise,
/// and so across a spline's crease), plus
/// the chord error of the face's boundary edges (the parts of the face outside
/// every parameter triangle lie between an edge and its polygon), plus how far
/// the triangle corners lie from the surface (rounding).
FaceSag face_sag(const TopoDS_Face& face, const Handle(Poly_Triangulation) & t,
                 const TopLoc_Location& loc);

}  // namespace pd
