// Bounds of a non-rational B-spline's second derivatives from its control net,
// for the certified chord error of its tessellation (geometry/
// interpolation_bound.h, src/brep/face_sag.cpp).
//
// Why they hold (de Boor; Piegl & Tiller, The NURBS Book, 3.3): the derivative
// of a B-spline of degree p with control points P_i on knots u is a B-spline
// of degree p − 1 with control points Q_i = p·(P_{i+1} − P_i)/(u_{i+p+1} −
// u_{i+1}) on basis functions N_{i+1,p−1} (a zero denominator belongs to a
// basis function that vanishes, and its term to nothing); likewise the second.
// Basis functions are non-negative and sum to one where they are defined, so a
// derivative lies in the convex hull of its control points there: its length
// is at most the longest of those whose basis function's support meets the
// parameter range. A tensor-product surface takes the same differences along
// each direction. The second derivative may jump at a knot where the spline is
// still C1 (the interpolation bound holds across it); at a knot of
// multiplicity ≥ degree the spline is only C0, and a range straddling that
// crease has no second-derivative bound: infinity.
#pragma once

#include <vector>

#include "geometry/interpolation_bound.h"
#include "geometry/types.h"

namespace pd {

/// A non-rational B-spline curve: poles, its full (flat) knot vector of
/// poles + degree + 1 values, and its degree.
struct SplineCurve {
  std::vector<Vec3> poles;
  std::vector<double> knots;
  int degree = 0;
};

/// A non-rational tensor-product B-spline surface: poles row by row
/// (pole(i, j) = poles[i · nv + j], i along u), flat knot vectors, degrees.
struct SplineSurface {
  int nu = 0, nv = 0;
  std::vector<Vec3> poles;
  std::vector<double> uknots, vknots;
  int udegree = 0, vdegree = 0;
};

/// An upper bound of |C''(t)| over t in [t0, t1]; infinity when a crease
/// (a C0 knot) lies strictly inside. Pure.
double spline_second_derivative_bound(const SplineCurve& c, double t0, double t1);

/// The control points of C' and C'' whose basis functions' supports meet
/// [t0, t1] (C' and C'' lie in their convex hulls there), and whether a crease
/// lies strictly inside. Pure.
struct CurveDerivativeNets {
  std::vector<Vec3> first, second;
  bool crease = false;
};
CurveDerivativeNets spline_derivative_nets(const SplineCurve& c, double t0, double t1);

/// An upper bound of the distance, either way, between a curve piece over a
/// parameter interval of length h and its chord (`chord` = C(t1) − C(t0)):
/// the least of
/// - h²/8 · max|C''| (each point within that of the chord point at the same
///   parameter), and
/// - h²/8 · max|C''⊥| + h · max(0, −min C'·d), d the chord's direction and
///   C''⊥ the part of C'' across it: the curve lies that close to the chord's
///   line, and runs back along it (beyond an end) at most h times its
///   steepest backward speed; the chord's points are covered by continuity.
///   A parameter that speeds up and slows down along a straight line has a
///   large |C''| and none of it across.
/// Infinity across a crease. Pure.
double chord_deviation_bound(const CurveDerivativeNets& n, const Vec3& chord, double h);

/// Upper bounds of |S_uu|, |S_uv| and |S_vv| over [u0, u1] × [v0, v1];
/// infinite |S_uu| (|S_vv|) when a u (v) crease lies strictly inside. Pure.
SecondDerivativeBounds spline_second_derivative_bounds(const SplineSurface& s, double u0, double u1,
                                                       double v0, double v1);

}  // namespace pd
