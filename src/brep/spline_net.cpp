#include "brep/spline_net.h"

#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_BezierSurface.hxx>
#include <Standard_Failure.hxx>
#include <algorithm>
#include <cmath>
#include <limits>

namespace pd {

namespace {

// Pieces per parameter direction: enough that a degree-8 single-span net
// bounds within a few times the truth, few enough to cost less than meshing.
constexpr int kSurfaceCells = 8;
constexpr int kCurveCells = 16;
constexpr double kInf = std::numeric_limits<double>::infinity();

// The surface as a non-rational, non-periodic B-spline; null otherwise.
Handle(Geom_BSplineSurface) bspline_of(const BRepAdaptor_Surface& s) {
  Handle(Geom_BSplineSurface) b;
  if (s.GetType() == GeomAbs_BezierSurface) {
    const Handle(Geom_BezierSurface) z = s.Bezier();
    if (z->IsURational() || z->IsVRational()) return nullptr;
    b = GeomConvert::SurfaceToBSplineSurface(z);
  } else if (s.GetType() == GeomAbs_BSplineSurface) {
    b = s.BSpline();
  }
  if (b.IsNull() || b->IsURational() || b->IsVRational()) return nullptr;
  if (b->IsUPeriodic() || b->IsVPeriodic()) {  // the same surface on a clamped knot vector
    b = Handle(Geom_BSplineSurface)::DownCast(b->Copy());
    if (b->IsUPeriodic()) b->SetUNotPeriodic();
    if (b->IsVPeriodic()) b->SetVNotPeriodic();
  }
  return b;
}

Handle(Geom_BSplineCurve) bspline_of(const Adaptor3d_Curve& c) {
  Handle(Geom_BSplineCurve) b;
  if (c.GetType() == GeomAbs_BezierCurve) {
    const Handle(Geom_BezierCurve) z = c.Bezier();
    if (z->IsRational()) return nullptr;
    b = GeomConvert::CurveToBSplineCurve(z);
  } else if (c.GetType() == GeomAbs_BSplineCurve) {
    b = c.BSpline();
  }
  if (b.IsNull() || b->IsRational()) return nullptr;
  if (b->IsPeriodic()) {
    b = Handle(Geom_BSplineCurve)::DownCast(b->Copy());
    b->SetNotPeriodic();
  }
  return b;
}

std::optional<SplineSurface> net_of(const Geom_BSplineSurface& b) {
  SplineSurface out;
  out.nu = b.NbUPoles();
  out.nv = b.NbVPoles();
  out.udegree = b.UDegree();
  out.vdegree = b.VDegree();
  for (int i = 1; i <= out.nu; ++i)
    for (int j = 1; j <= out.nv; ++j) {
      const gp_Pnt& q = b.Pole(i, j);
      out.poles.emplace_back(q.X(), q.Y(), q.Z());
    }
  const TColStd_Array1OfReal& ku = b.UKnotSequence();
  for (int k = ku.Lower(); k <= ku.Upper(); ++k) out.uknots.push_back(ku(k));
  const TColStd_Array1OfReal& kv = b.VKnotSequence();
  for (int k = kv.Lower(); k <= kv.Upper(); ++k) out.vknots.push_back(kv(k));
  if (out.uknots.size() != size_t(out.nu + out.udegree + 1) ||
      out.vknots.size() != size_t(out.nv + out.vdegree + 1))
    return std::nullopt;  // not the layout the bound reads
  return out;
}

std::optional<SplineCurve> net_of(const Geom_BSplineCurve& b) {
  SplineCurve out;
  out.degree = b.Degree();
  for (int i = 1; i <= b.NbPoles(); ++i)
    out.poles.emplace_back(b.Pole(i).X(), b.Pole(i).Y(), b.Pole(i).Z());
  const TColStd_Array1OfReal& k = b.KnotSequence();
  for (int i = k.Lower(); i <= k.Upper(); ++i) out.knots.push_back(k(i));
  if (out.knots.size() != out.poles.size() + size_t(out.degree) + 1) return std::nullopt;
  return out;
}

// The cells [lo, hi] of a range split into n, clipped to the spline's own range.
struct Grid {
  double lo, hi;
  int n;
  double at(int i) const { return lo + (hi - lo) * i / n; }
  // The cells meeting [a, b].
  std::pair<int, int> cells(double a, double b) const {
    const auto index = [&](double x) {
      const double f = hi > lo ? (x - lo) / (hi - lo) * n : 0.0;
      return std::clamp(int(std::floor(f)), 0, n - 1);
    };
    return {index(a), index(b)};
  }
};

SecondDerivativeBounds max_of(const SecondDerivativeBounds& a, const SecondDerivativeBounds& b) {
  return {std::max(a.uu, b.uu), std::max(a.uv, b.uv), std::max(a.vv, b.vv)};
}
SecondDerivativeBounds min_of(const SecondDerivativeBounds& a, const SecondDerivativeBounds& b) {
  return {std::min(a.uu, b.uu), std::min(a.uv, b.uv), std::min(a.vv, b.vv)};
}

}  // namespace

std::optional<SurfaceNetBounds> SurfaceNetBounds::of(const BRepAdaptor_Surface& s, double u0,
                                                     double u1, double v0, double v1) {
  const Handle(Geom_BSplineSurface) b = bspline_of(s);
  if (b.IsNull()) return std::nullopt;
  const std::optional<SplineSurface> whole = net_of(*b);
  if (!whole) return std::nullopt;
  SurfaceNetBounds out;
  out.whole_ = *whole;
  double bu0, bu1, bv0, bv1;
  b->Bounds(bu0, bu1, bv0, bv1);
  out.u0_ = std::max(u0, bu0);
  out.u1_ = std::min(u1, bu1);
  out.v0_ = std::max(v0, bv0);
  out.v1_ = std::min(v1, bv1);
  out.n_ = (out.u1_ > out.u0_ && out.v1_ > out.v0_) ? kSurfaceCells : 0;
  const Grid gu{out.u0_, out.u1_, out.n_}, gv{out.v0_, out.v1_, out.n_};
  for (int i = 0; i < out.n_; ++i)
    for (int j = 0; j < out.n_; ++j) {
      const double a = gu.at(i), c = gu.at(i + 1), d = gv.at(j), e = gv.at(j + 1);
      SecondDerivativeBounds m{kInf, kInf, kInf};  // a piece OCCT cannot cut: the whole net
      try {
        const Handle(Geom_BSplineSurface) piece = Handle(Geom_BSplineSurface)::DownCast(b->Copy());
        piece->Segment(a, c, d, e);
        if (const std::optional<SplineSurface> net = net_of(*piece))
          m = spline_second_derivative_bounds(*net, a, c, d, e);
      } catch (const Standard_Failure&) {
      }
      out.cell_.push_back(m);
    }
  return out;
}

SecondDerivativeBounds SurfaceNetBounds::over(double u0, double u1, double v0, double v1) const {
  const SecondDerivativeBounds whole = spline_second_derivative_bounds(whole_, u0, u1, v0, v1);
  // A box reaching outside the cut range (boundary rounding) reads the whole net.
  if (n_ == 0 || u0 < u0_ || u1 > u1_ || v0 < v0_ || v1 > v1_) return whole;
  const Grid gu{u0_, u1_, n_}, gv{v0_, v1_, n_};
  const auto [i0, i1] = gu.cells(u0, u1);
  const auto [j0, j1] = gv.cells(v0, v1);
  SecondDerivativeBounds m;
  for (int i = i0; i <= i1; ++i)
    for (int j = j0; j <= j1; ++j) m = max_of(m, cell_[size_t(i * n_ + j)]);
  // Both are bounds; a crease between cells leaves the cells' maximum finite
  // where the triangle straddles it, so the whole net's crease test decides.
  if (!std::isfinite(whole.uu)) m.uu = kInf;
  if (!std::isfinite(whole.vv)) m.vv = kInf;
  return min_of(m, whole);
}

std::optional<CurveNetBounds> CurveNetBounds::of(const Adaptor3d_Curve& c, double t0, double t1) {
  const Handle(Geom_BSplineCurve) b = bspline_of(c);
  if (b.IsNull()) return std::nullopt;
  const std::optional<SplineCurve> whole = net_of(*b);
  if (!whole) return std::nullopt;
  CurveNetBounds out;
  out.whole_ = *whole;
  out.t0_ = std::max(std::min(t0, t1), b->FirstParameter());
  out.t1_ = std::min(std::max(t0, t1), b->LastParameter());
  const int n = out.t1_ > out.t0_ ? kCurveCells : 0;
  const Grid g{out.t0_, out.t1_, n};
  for (int i = 0; i < n; ++i) {
    const double a = g.at(i), e = g.at(i + 1);
    std::optional<SplineCurve> net;
    try {
      const Handle(Geom_BSplineCurve) piece = Handle(Geom_BSplineCurve)::DownCast(b->Copy());
      piece->Segment(a, e);
      net = net_of(*piece);
    } catch (const Standard_Failure&) {
    }
    if (!net) return out.cell_.clear(), out;  // a piece OCCT cannot cut: the whole net
    out.cell_.push_back(spline_derivative_nets(*net, a, e));
  }
  return out;
}

std::optional<CurveDerivativeNets> CurveNetBounds::pieces(double a, double b) const {
  const int n = int(cell_.size());
  if (n == 0 || a < t0_ || b > t1_) return std::nullopt;
  const auto [i0, i1] = Grid{t0_, t1_, n}.cells(a, b);
  CurveDerivativeNets out;
  for (int i = i0; i <= i1; ++i) {
    const CurveDerivativeNets& c = cell_[size_t(i)];
    out.first.insert(out.first.end(), c.first.begin(), c.first.end());
    out.second.insert(out.second.end(), c.second.begin(), c.second.end());
  }
  // A piece's own crease test spans the whole piece; the whole net's knows
  // whether [a, b] straddles one.
  return out;
}

double CurveNetBounds::over(double a, double b) const {
  const double whole = spline_second_derivative_bound(whole_, a, b);
  const std::optional<CurveDerivativeNets> p = pieces(a, b);
  if (!p || !std::isfinite(whole)) return whole;
  double m = 0.0;
  for (const Vec3& q : p->second) m = std::max(m, q.norm());
  return std::min(m, whole);
}

double CurveNetBounds::chord_deviation(double a, double b, const Vec3& chord) const {
  const CurveDerivativeNets whole = spline_derivative_nets(whole_, a, b);
  const double from_whole = chord_deviation_bound(whole, chord, b - a);
  const std::optional<CurveDerivativeNets> p = pieces(a, b);
  if (!p || whole.crease) return from_whole;
  return std::min(from_whole, chord_deviation_bound(*p, chord, b - a));
}

}  // namespace pd
