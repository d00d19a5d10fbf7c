// Second-derivative bounds of Open CASCADE's non-rational splines, read from
// their control nets (geometry/spline_bound.h) piece by piece (internal to
// src/brep: names Open CASCADE types).
//
// Why piece by piece: the control net of a whole high-degree approximant (what
// STEP exporters and GeomAPI write: degree 5–8 over one span) oscillates
// around the surface, and its differences overstate the second derivative
// fifty-fold. Knot insertion (Geom_BSplineSurface::Segment) gives the net of a
// small piece, which converges to the surface quadratically as the piece
// shrinks: the bound of each triangle is read from the pieces it meets.
#pragma once

#include <Adaptor3d_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <optional>
#include <vector>

#include "geometry/interpolation_bound.h"
#include "geometry/spline_bound.h"

namespace pd {

/// A non-rational B-spline or Bézier surface's second-derivative bounds over
/// parameter boxes inside [u0, u1] × [v0, v1] (the face's range).
class SurfaceNetBounds {
 public:
  /// nullopt when `s` is not a non-rational B-spline or Bézier surface.
  static std::optional<SurfaceNetBounds> of(const BRepAdaptor_Surface& s, double u0, double u1,
                                            double v0, double v1);
  /// Bounds of |S_uu|, |S_uv|, |S_vv| over the box; infinite |S_uu| (|S_vv|)
  /// across a crease.
  SecondDerivativeBounds over(double u0, double u1, double v0, double v1) const;

 private:
  SplineSurface whole_;
  double u0_ = 0, u1_ = 0, v0_ = 0, v1_ = 0;
  int n_ = 0;                                 // cells per direction
  std::vector<SecondDerivativeBounds> cell_;  // n_ × n_, row i along u
};

/// The same for a non-rational B-spline or Bézier curve over [t0, t1].
class CurveNetBounds {
 public:
  static std::optional<CurveNetBounds> of(const Adaptor3d_Curve& c, double t0, double t1);
  /// A bound of |C''| over [a, b]; infinite across a crease.
  double over(double a, double b) const;
  /// A bound of how far C over [a, b] lies from its chord C(b) − C(a),
  /// either way (chord_deviation_bound).
  double chord_deviation(double a, double b, const Vec3& chord) const;

 private:
  // The derivative nets of the pieces meeting [a, b] (nullopt: read the whole net).
  std::optional<CurveDerivativeNets> pieces(double a, double b) const;

  SplineCurve whole_;
  double t0_ = 0, t1_ = 0;
  std::vector<CurveDerivativeNets> cell_;
};

}  // namespace pd
