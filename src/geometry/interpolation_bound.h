// How far a map of the plane lies from its linear interpolation over a
// triangle: the certified chord error of a tessellated parametric surface
// (src/brep/tessellate.cpp) or curve, from bounds of its second derivatives.
//
// Why it holds (Waldron 1998, "The error in linear interpolation at the
// vertices of a simplex"): let e = n·(S − L S) for a unit vector n, where L S
// interpolates S linearly at the corners, so e vanishes at them. If every
// second directional derivative of S is at most M long, h(y) = e(y) + (M/2)|y −
// c|² is convex for any centre c, so on the triangle it is at most its largest
// corner value, (M/2)·max|x_i − c|². With c the centre of the smallest circle
// holding the triangle (radius R): e ≤ (M/2)·R², for every n, hence |S − L S|
// ≤ (M/2)·R² everywhere on the triangle. The same with a segment (R half its
// length) for a curve.
//
// A surface's parameters rarely share a scale (a cylinder's u is an angle, its
// v a length), and the bound holds in any linear rescaling of them: each call
// takes the best of a range of scalings of u.
#pragma once

#include <Eigen/Core>
#include <array>
#include <functional>

namespace pd {

using Vec2 = Eigen::Vector2d;

/// Bounds of the second partial derivatives of S: R² → R³ over a parameter
/// region: |S_uu| ≤ uu, |S_uv| ≤ uv, |S_vv| ≤ vv (lengths of vectors).
struct SecondDerivativeBounds {
  double uu = 0.0, uv = 0.0, vv = 0.0;
};

/// The radius of the smallest circle holding the triangle (a, b, c): half the
/// longest side when the triangle is right or obtuse, else its circumradius.
double smallest_enclosing_radius(const Vec2& a, const Vec2& b, const Vec2& c);

/// An upper bound of max |S(p) − (L S)(p)| over the parameter triangle `uv`,
/// L S the linear interpolation of S at its corners, when the second
/// derivatives of S on the triangle are bounded by `m`. 0 when every bound is 0
/// (a plane). Pure.
double triangle_interpolation_bound(const std::array<Vec2, 3>& uv, const SecondDerivativeBounds& m);

/// A sharper bound of max |S(p) − (L P)(p)| over the parameter triangle `uv`,
/// L P interpolating the points P_i stored for its corners (on S up to
/// rounding): `error(w)` measures |S − L P| at the point of barycentric weights
/// w. The triangle is cut into n² copies of itself scaled by 1/n; on each, S −
/// L P is its linear interpolation at the copy's corners (a convex combination
/// of measured errors, no longer than the largest) plus S's own interpolation
/// error there, at most triangle_interpolation_bound / n². So the result is the
/// largest error measured at the (n + 1)(n + 2)/2 grid points plus that
/// remainder: within coarse/n² of the true error, where the coarse bound alone
/// can be twice it (a saddle, a torus's inner side). n ≥ 1. Pure if `error` is.
double refined_interpolation_bound(const std::array<Vec2, 3>& uv, const SecondDerivativeBounds& m,
                                   int n,
                                   const std::function<double(const Eigen::Vector3d&)>& error);

/// An upper bound of max |C(t) − (L C)(t)| over [t0, t1] for a curve whose
/// second derivative is at most `m` long there: m·(t1 − t0)²/8.
double segment_interpolation_bound(double t0, double t1, double m);

}  // namespace pd
