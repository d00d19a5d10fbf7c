#include "brep/face_sag.h"

#include <Adaptor3d_Curve.hxx>
#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Curve2d.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRep_Tool.hxx>
#include <Poly_PolygonOnTriangulation.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <array>
#include <cmath>
#include <gp_Circ.hxx>
#include <gp_Cone.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Elips.hxx>
#include <gp_Hypr.hxx>
#include <gp_Parab.hxx>
#include <gp_Sphere.hxx>
#include <gp_Torus.hxx>
#include <optional>

#include "brep/spline_net.h"
#include "geometry/interpolation_bound.h"
#include "geometry/triangle_tree.h"
#include "tolerances.h"

namespace pd {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Whether [a, b] holds a + k·period point `at` (mod period).
bool holds(double a, double b, double at, double period) {
  const double k = std::ceil((a - at) / period);
  return at + k * period <= b;
}

// The range of cos and the largest |sin| over [a, b].
struct TrigRange {
  double cos_min, cos_max, sin_abs;
};
TrigRange trig_range(double a, double b) {
  TrigRange r;
  r.cos_max = holds(a, b, 0.0, 2 * kPi) ? 1.0 : std::max(std::cos(a), std::cos(b));
  r.cos_min = holds(a, b, kPi, 2 * kPi) ? -1.0 : std::min(std::cos(a), std::cos(b));
  r.sin_abs =
      holds(a, b, kPi / 2, kPi) ? 1.0 : std::max(std::abs(std::sin(a)), std::abs(std::sin(b)));
  return r;
}

// The spline nets a face's bounds read: its surface's, or its extrusion's basis curve's.
struct SplineNets {
  std::optional<SurfaceNetBounds> surface;
  std::optional<CurveNetBounds> basis;
};

// Bounds of the second derivatives of an analytic surface over the parameter
// box [u0, u1] × [v0, v1] (OCCT's parametrisations, ElSLib), or of a
// non-rational spline's (`nets`: the face's own, or an extrusion's basis
// curve's), or of an extrusion C(u) + v·D (only S_uu = C''(u): lines, circles
// and non-rational splines); false for any other surface.
bool analytic_bounds(const BRepAdaptor_Surface& s, const SplineNets& nets, double u0, double u1,
                     double v0, double v1, SecondDerivativeBounds& m) {
  if (nets.surface) {
    m = nets.surface->over(u0, u1, v0, v1);
    return true;
  }
  if (s.GetType() == GeomAbs_SurfaceOfExtrusion) {
    const Handle(Adaptor3d_Curve) c = s.BasisCurve();
    m = {};
    if (c->GetType() == GeomAbs_Line) return true;
    if (c->GetType() == GeomAbs_Circle) {
      m.uu = c->Circle().Radius();
      return true;
    }
    if (!nets.basis) return false;
    m.uu = nets.basis->over(u0, u1);
    return true;
  }
  switch (s.GetType()) {
    case GeomAbs_Plane:
      m = {};
      return true;
    case GeomAbs_Cylinder:  // O + r(cos u X + sin u Y) + v Z
      m = {s.Cylinder().Radius(), 0.0, 0.0};
      return true;
    case GeomAbs_Cone: {  // O + (r + v sin α)(cos u X + sin u Y) + v cos α Z
      const gp_Cone c = s.Cone();
      const double sa = std::sin(c.SemiAngle());
      const double at0 = std::abs(c.RefRadius() + v0 * sa), at1 = std::abs(c.RefRadius() + v1 * sa);
      m = {std::max(at0, at1), std::abs(sa), 0.0};
      return true;
    }
    case GeomAbs_Sphere: {  // O + r cos v (cos u X + sin u Y) + r sin v Z
      const double r = s.Sphere().Radius();
      const TrigRange t = trig_range(v0, v1);
      m = {r * std::max(std::abs(t.cos_min), std::abs(t.cos_max)), r * t.sin_abs, r};
      return true;
    }
    case GeomAbs_Torus: {  // O + (R + r cos v)(cos u X + sin u Y) + r sin v Z
      const gp_Torus t = s.Torus();
      const double big = t.MajorRadius(), r = t.MinorRadius();
      const TrigRange g = trig_range(v0, v1);
      m = {std::max(std::abs(big + r * g.cos_min), std::abs(big + r * g.cos_max)), r * g.sin_abs,
           r};
      return true;
    }
    default:
      return false;
  }
}

// The nets of a face's spline surface or extrusion basis over the parameter
// range its triangles cover.
SplineNets spline_nets(const BRepAdaptor_Surface& s, const Poly_Triangulation& t) {
  SplineNets out;
  const bool spline = s.GetType() == GeomAbs_BSplineSurface || s.GetType() == GeomAbs_BezierSurface;
  const bool extrusion = s.GetType() == GeomAbs_SurfaceOfExtrusion;
  if (!spline && !extrusion) return out;
  double u0 = HUGE_VAL, u1 = -HUGE_VAL, v0 = HUGE_VAL, v1 = -HUGE_VAL;
  for (int k = 1; k <= t.NbNodes(); ++k) {
    const gp_Pnt2d q = t.UVNode(k);
    u0 = std::min(u0, q.X());
    u1 = std::max(u1, q.X());
    v0 = std::min(v0, q.Y());
    v1 = std::max(v1, q.Y());
  }
  if (spline) out.surface = SurfaceNetBounds::of(s, u0, u1, v0, v1);
  if (extrusion) out.basis = CurveNetBounds::of(*s.BasisCurve(), u0, u1);
  return out;
}

// The distance between the surface and the flat triangle sampled at seven
// points (its centroid, edge midpoints and the points halfway to the corners):
// an estimate for free-form faces.
double sampled_deviation(const BRepAdaptor_Surface& s, const std::array<gp_Pnt2d, 3>& uv,
                         const std::array<gp_Pnt, 3>& p) {
  static const double kWeights[7][3] = {{1 / 3., 1 / 3., 1 / 3.},
                                        {.5, .5, 0},
                                        {0, .5, .5},
                                        {.5, 0, .5},
                                        {2 / 3., 1 / 6., 1 / 6.},
                                        {1 / 6., 2 / 3., 1 / 6.},
                                        {1 / 6., 1 / 6., 2 / 3.}};
  double worst = 0.0;
  for (const auto& w : kWeights) {
    const double u = w[0] * uv[0].X() + w[1] * uv[1].X() + w[2] * uv[2].X();
    const double v = w[0] * uv[0].Y() + w[1] * uv[1].Y() + w[2] * uv[2].Y();
    const gp_XYZ flat = w[0] * p[0].XYZ() + w[1] * p[1].XYZ() + w[2] * p[2].XYZ();
    worst = std::max(worst, (s.Value(u, v).XYZ() - flat).Modulus());
  }
  return worst;
}

// The chord error of one boundary edge's polygon on the face's triangulation.
FaceSag edge_sag(const TopoDS_Edge& e, const Poly_Triangulation& t, const TopLoc_Location& loc,
                 const Handle(Poly_Triangulation) & handle) {
  // Polygons of an edge are found by the triangulation they lie on.
  FaceSag out;
  if (BRep_Tool::Degenerated(e)) return out;
  const Handle(Poly_PolygonOnTriangulation)& poly =
      BRep_Tool::PolygonOnTriangulation(e, handle, loc);
  if (poly.IsNull() || poly->NbNodes() < 2) return out;
  BRepAdaptor_Curve c(e);
  const GeomAbs_CurveType type = c.GetType();
  if (type == GeomAbs_Line) return out;
  const bool params = poly->HasParameters();
  std::optional<CurveNetBounds> spline;
  if (params) spline = CurveNetBounds::of(c, poly->Parameter(1), poly->Parameter(poly->NbNodes()));
  const gp_Trsf to_world = loc.Transformation();
  for (int k = 1; k < poly->NbNodes(); ++k) {
    const gp_Pnt a = t.Node(poly->Node(k)).Transformed(to_world);
    const gp_Pnt b = t.Node(poly->Node(k + 1)).Transformed(to_world);
    if (!params) {  // nothing to bound the arc with: estimate from the chord's middle
      out.bound = false;
      continue;
    }
    const double t0 = poly->Parameter(k), t1 = poly->Parameter(k + 1);
    const Vec3 chord(b.X() - a.X(), b.Y() - a.Y(), b.Z() - a.Z());
    double dev = INFINITY;  // a bound where one is known (a spline's is infinite across a crease)
    if (spline) {
      dev = spline->chord_deviation(std::min(t0, t1), std::max(t0, t1),
                                    t0 < t1 ? chord : Vec3(-chord));
    } else if (type == GeomAbs_Circle) {
      const double r = c.Circle().Radius();
      dev = r * (1.0 - std::cos(0.5 * std::abs(t1 - t0)));
    } else if (type == GeomAbs_Ellipse) {
      dev = segment_interpolation_bound(t0, t1, c.Ellipse().MajorRadius());
    } else if (type == GeomAbs_Hyperbola) {
      // C(t) = (a cosh t, b sinh t): |C''| = |C − centre| grows with |t|, so it
      // is largest at the segment's end farther from the vertex (a chamfer's
      // cone cut by a hexagon's flat: every chamfered hex head and nut).
      const gp_Hypr h = c.Hyperbola();
      const double far = std::max(std::abs(t0), std::abs(t1));
      dev = segment_interpolation_bound(
          t0, t1, std::hypot(h.MajorRadius() * std::cosh(far), h.MinorRadius() * std::sinh(far)));
    } else if (type == GeomAbs_Parabola) {
      // C(t) = (t² / 4f, t): |C''| = 1 / 2f everywhere.
      dev = segment_interpolation_bound(t0, t1, 0.5 / c.Parabola().Focal());
    }
    if (!std::isfinite(dev)) {
      out.bound = false;
      const double mid = 0.5 * (t0 + t1);
      dev = (c.Value(mid).XYZ() - 0.5 * (a.XYZ() + b.XYZ())).Modulus();
    }
    // The polygon's corners as stored may lie off the curve by rounding.
    dev += std::max(c.Value(t0).Distance(a), c.Value(t1).Distance(b));
    out.value = std::max(out.value, dev);
  }
  return out;
}

// Whether the edge's curve on the face is a straight line in its parameters.
bool straight_in_parameters(const TopoDS_Edge& e, const TopoDS_Face& f) {
  double first = 0.0, last = 0.0;
  if (BRep_Tool::CurveOnSurface(e, f, first, last).IsNull()) return false;
  return BRepAdaptor_Curve2d(e, f).GetType() == GeomAbs_Line;
}

}  // namespace

FaceSag face_sag(const TopoDS_Face& face, const Handle(Poly_Triangulation) & handle,
                 const TopLoc_Location& loc) {
  FaceSag out;
  const Poly_Triangulation& t = *handle;
  BRepAdaptor_Surface s(face);  // placed by the face's location, as the nodes are by `loc`
  const gp_Trsf to_world = loc.Transformation();
  const bool has_uv = t.HasUVNodes();
  const SplineNets nets = has_uv ? spline_nets(s, t) : SplineNets{};
  double triangles = 0.0;
  for (int k = 1; k <= t.NbTriangles(); ++k) {
    int i[3];
    t.Triangle(k).Get(i[0], i[1], i[2]);
    std::array<gp_Pnt, 3> p;
    std::array<gp_Pnt2d, 3> uv;
    for (int c = 0; c < 3; ++c) {
      p[c] = t.Node(i[c]).Transformed(to_world);
      if (has_uv) uv[c] = t.UVNode(i[c]);
    }
    if (!has_uv) {
      out.bound = false;
      continue;
    }
    double corner = 0.0;  // the corners as stored against the surface at their parameters
    for (int c = 0; c < 3; ++c)
      corner = std::max(corner, s.Value(uv[c].X(), uv[c].Y()).Distance(p[c]));
    const double u0 = std::min({uv[0].X(), uv[1].X(), uv[2].X()});
    const double u1 = std::max({uv[0].X(), uv[1].X(), uv[2].X()});
    const double v0 = std::min({uv[0].Y(), uv[1].Y(), uv[2].Y()});
    const double v1 = std::max({uv[0].Y(), uv[1].Y(), uv[2].Y()});
    SecondDerivativeBounds m;
    double dev = INFINITY;  // a bound where one is known (a spline's is infinite across a crease)
    if (s.GetType() == GeomAbs_Sphere) {
      // The triangle lies inside the sphere (its corners are on it), at most
      // r − d(c, T) from it; every point of the sphere lies on a ray from the
      // centre through some triangle, no farther from it. Exact, where the
      // parametrisation's derivatives blow up at the poles.
      const gp_Sphere sphere = s.Sphere();
      const Vec3 c(sphere.Location().X(), sphere.Location().Y(), sphere.Location().Z());
      const auto v = [](const gp_Pnt& q) { return Vec3(q.X(), q.Y(), q.Z()); };
      const Vec3 near = closest_on_triangle(c, v(p[0]), v(p[1]), v(p[2]));
      dev = std::max(0.0, sphere.Radius() - (near - c).norm());
    } else if (analytic_bounds(s, nets, u0, u1, v0, v1, m)) {
      const std::array<Vec2, 3> at{Vec2(uv[0].X(), uv[0].Y()), Vec2(uv[1].X(), uv[1].Y()),
                                   Vec2(uv[2].X(), uv[2].Y())};
      dev = triangle_interpolation_bound(at, m);
      // Only a triangle that would raise the face's sag is worth measuring:
      // the coarse bound can be twice the error (a torus's, a spline's).
      if (std::isfinite(dev)) {
        if (dev + corner > triangles) {
          const double sharp = refined_interpolation_bound(
              at, m, tol::kSagRefineCuts, [&](const Eigen::Vector3d& w) {
                const Vec2 q = w[0] * at[0] + w[1] * at[1] + w[2] * at[2];
                const gp_XYZ flat = w[0] * p[0].XYZ() + w[1] * p[1].XYZ() + w[2] * p[2].XYZ();
                return (s.Value(q.x(), q.y()).XYZ() - flat).Modulus();
              });
          // The measured errors hold the corners' offsets already.
          triangles = std::max(triangles, std::min(dev + corner, sharp));
        }
        continue;
      }
    }
    if (!std::isfinite(dev)) {
      out.bound = false;
      dev = sampled_deviation(s, uv, p);
    }
    triangles = std::max(triangles, dev + corner);
  }
  double edges = 0.0;
  for (TopExp_Explorer x(face, TopAbs_EDGE); x.More(); x.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(x.Current());
    // An edge straight in the face's parameters (a cylinder's or torus's
    // circle, a seam) bounds the triangles exactly: its polygon's parameters
    // lie on that line, so no strip of the face lies beyond the triangles and
    // the triangles' own bound already covers the chords.
    if (has_uv && straight_in_parameters(edge, face)) continue;
    const FaceSag e = edge_sag(edge, t, loc, handle);
    edges = std::max(edges, e.value);
    out.bound = out.bound && e.bound;
  }
  out.value = triangles + edges;
  return out;
}

}  // namespace pd
