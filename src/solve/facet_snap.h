// The final snap of a direction onto the optimal facet of P − Q.
//
// At a local optimum of the gap the supporting plane is a facet of the
// Minkowski difference: a face of P (the vertices with p·v maximal) minus a face
// of Q (q·v minimal) spanning a plane. Its normal is exactly orthogonal to every
// edge between active vertices. Computing that normal from the vertices makes
// the depth exact to rounding, where an iterative solver stops at its tolerance.
#pragma once

#include <optional>

#include "geometry/types.h"

namespace pd {

/// The facet normal for the vertices active at v (oriented with v), or nothing
/// when the active vertices do not span a plane at any tried tolerance.
std::optional<Vec3> snap_to_facet(const Points& p, const Points& q, const Vec3& v);

/// The same from a smooth descent's end point, which lies within about μ of the
/// optimum: active sets from kDescentSnapBand down to the tight ones. On a
/// contact (faces resting on faces) it lands on the contact facet without any
/// Ipopt call. Only a candidate: the caller keeps it only if its gap is lower.
std::optional<Vec3> snap_from_descent(const Points& p, const Points& q, const Vec3& v);

}  // namespace pd
