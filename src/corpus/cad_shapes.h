// Closed triangle meshes of CAD-like parts whose geometry is known by
// construction (plates with bolt holes, bolts, L-brackets, hollow boxes), for
// the tests and measurements of the nonconvex-part functions. Every mesh is
// watertight with outward counter-clockwise triangles.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/mesh.h"

namespace pd::shapes {

using Vec2 = Eigen::Vector2d;

/// The box [lo, hi]: 8 vertices, 12 triangles.
Mesh box(const Vec3& lo, const Vec3& hi);

/// A simple counter-clockwise polygon (x, y) extruded from z0 to z1; the caps
/// are ear-clipped, so the polygon may be nonconvex.
Mesh prism(const std::vector<Vec2>& polygon, double z0, double z1);

/// The regular polygon of `segments` vertices on the circle of `radius` about
/// `centre`, the first at angle `phase` (radians).
std::vector<Vec2> circle(const Vec2& centre, double radius, int segments, double phase = 0.0);

/// A cylinder along z: prism of circle(centre, radius, segments).
Mesh cylinder(const Vec2& centre, double radius, double z0, double z1, int segments);

/// A square plate [-side/2, side/2]² × [0, thickness] with a through hole:
/// the polygon circle({0, 0}, hole_radius, segments). segments must be a
/// multiple of 8 (the square's corners are outline vertices at 45°, 135°, …).
Mesh plate_with_hole(double side, double thickness, double hole_radius, int segments);

/// A board [0, nx·pitch] × [0, ny·pitch] × [0, thickness] with a round hole
/// (circle of hole_radius, `segments`, a multiple of 8) in the centre of each
/// pitch × pitch cell, as one watertight mesh (cells share their edge vertices).
Mesh drilled_board(int nx, int ny, double pitch, double thickness, double hole_radius,
                   int segments);

/// An L-bracket: the L { [0, a]×[0, t] ∪ [0, t]×[0, a] } in (x, y), extruded
/// over z in [0, width]. Its inner corner is at (t, t).
Mesh l_bracket(double a, double t, double width);

/// The box [lo, hi] with a closed cavity: walls `wall` thick, the inner shell
/// oriented inward (two shells, one solid with a void).
Mesh hollow_box(const Vec3& lo, const Vec3& hi, double wall);

/// A stepped shaft along z as one closed shell: a shank of `shank_radius`
/// from z0 to z1 under a head of `head_radius` from z1 to z2, both the regular
/// polygon of `segments` (phase 0); the shoulder at z1 is a concave edge.
Mesh stepped_shaft(double shank_radius, double head_radius, double z0, double z1, double z2,
                   int segments);

/// The solid of revolution about the z axis of a closed profile polygon in the
/// (ρ, z) half-plane (ρ >= 0, counter-clockwise): each profile point with ρ > 0
/// becomes a ring of `segments` vertices on its true circle (the first at
/// angle 0), one with ρ = 0 a single vertex on the axis. Watertight, outward.
/// Cylinders, tubes (a bore is their inner wall), UV spheres, tori and cones.
Mesh revolution(const std::vector<Vec2>& profile, int segments);

/// Every vertex moved by `offset`.
Mesh translated(Mesh m, const Vec3& offset);

/// Every coordinate rounded to float32 (as an STL file stores it).
Mesh float32(Mesh m);

/// The meshes as one (triangle indices offset).
Mesh joined(const std::vector<Mesh>& parts);

/// The mesh with every triangle reversed (inward normals).
Mesh flipped(Mesh m);

}  // namespace pd::shapes
