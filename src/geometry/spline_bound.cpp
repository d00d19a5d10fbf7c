#include "geometry/spline_bound.h"

#include <algorithm>
#include <limits>

namespace pd {

namespace {

// The control points of the derivative of a degree-p B-spline with control
// points `c` on flat knots `k` (degree p − 1, control point i on basis
// function N_{i+1,p−1}, supported on [k_{i+1}, k_{i+p+1}]).
template <class Point>
std::vector<Point> derivative(const std::vector<Point>& c, const std::vector<double>& k, int p) {
  std::vector<Point> out;
  if (c.size() < 2) return out;
  for (size_t i = 0; i + 1 < c.size(); ++i) {
    const double span = k[i + size_t(p) + 1] - k[i + 1];
    out.push_back(span > 0 ? Point(p * (c[i + 1] - c[i]) / span) : Point(0 * c[i]));
  }
  return out;
}

// Whether basis function N_{first,degree} on knots k, supported on
// [k_first, k_{first+degree+1}], meets [a, b].
bool meets(const std::vector<double>& k, size_t first, int degree, double a, double b) {
  const size_t last = first + size_t(degree) + 1;
  if (last >= k.size()) return true;  // at the end of the vector: keep (a bound only loosens)
  return k[first] <= b && k[last] >= a;
}

// Whether a knot of multiplicity ≥ degree (where the spline is only C0: a
// crease, its second derivative a Dirac mass) lies strictly inside (a, b).
// The end knots (a clamped vector's first and last values) are no creases:
// nothing lies beyond them, though a range may reach past them by rounding.
bool crease_inside(const std::vector<double>& k, int degree, double a, double b) {
  if (degree < 1 || k.empty()) return false;
  for (size_t i = 0; i < k.size();) {
    size_t j = i;
    while (j < k.size() && k[j] == k[i]) ++j;
    const bool end = i == 0 || j == k.size();
    if (!end && k[i] > a && k[i] < b && j - i >= size_t(degree)) return true;
    i = j;
  }
  return false;
}

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

}  // namespace

CurveDerivativeNets spline_derivative_nets(const SplineCurve& c, double t0, double t1) {
  CurveDerivativeNets out;
  out.crease = crease_inside(c.knots, c.degree, t0, t1);
  if (c.degree < 1) return out;
  const std::vector<Vec3> d1 = derivative(c.poles, c.knots, c.degree);
  for (size_t i = 0; i < d1.size(); ++i)
    if (meets(c.knots, i + 1, c.degree - 1, t0, t1)) out.first.push_back(d1[i]);
  if (c.degree < 2) return out;
  // The first derivative's knots are the same vector shifted by one: its
  // control point i sits on N_{i+1,p−1}, so its own derivative uses k_{i+1}….
  const std::vector<double> shifted(c.knots.begin() + 1, c.knots.end());
  const std::vector<Vec3> d2 = derivative(d1, shifted, c.degree - 1);
  for (size_t i = 0; i < d2.size(); ++i)
    if (meets(c.knots, i + 2, c.degree - 2, t0, t1)) out.second.push_back(d2[i]);
  return out;
}

double chord_deviation_bound(const CurveDerivativeNets& n, const Vec3& chord, double h) {
  if (n.crease) return kUnbounded;
  double whole = 0.0, across = 0.0, back = 0.0;
  const double length = chord.norm();
  const Vec3 d = length > 0 ? Vec3(chord / length) : Vec3::Zero();
  for (const Vec3& q : n.first) back = std::max(back, -q.dot(d));
  for (const Vec3& q : n.second) {
    whole = std::max(whole, q.norm());
    across = std::max(across, (q - q.dot(d) * d).norm());
  }
  const double h2 = h * h / 8.0;
  if (!(length > 0)) return h2 * whole;
  return std::min(h2 * whole, h2 * across + h * back);
}

double spline_second_derivative_bound(const SplineCurve& c, double t0, double t1) {
  const CurveDerivativeNets n = spline_derivative_nets(c, t0, t1);
  if (n.crease) return kUnbounded;
  double m = 0.0;
  for (const Vec3& q : n.second) m = std::max(m, q.norm());
  return m;
}

SecondDerivativeBounds spline_second_derivative_bounds(const SplineSurface& s, double u0, double u1,
                                                       double v0, double v1) {
  using Row = std::vector<Vec3>;
  const auto pole = [&](int i, int j) { return s.poles[size_t(i) * size_t(s.nv) + size_t(j)]; };
  const std::vector<double> ushift(s.uknots.begin() + 1, s.uknots.end());
  const std::vector<double> vshift(s.vknots.begin() + 1, s.vknots.end());
  SecondDerivativeBounds m;
  // A crease across u makes S_uu a Dirac mass; S_v stays continuous across
  // it, so S_uv keeps its bound (likewise in v).
  if (crease_inside(s.uknots, s.udegree, u0, u1)) m.uu = kUnbounded;
  if (crease_inside(s.vknots, s.vdegree, v0, v1)) m.vv = kUnbounded;
  // Along u: per column j, the first and second differences in i.
  std::vector<Row> du(size_t(s.nv));  // du[j][i]: first u-derivative's control points
  for (int j = 0; j < s.nv; ++j) {
    Row col;
    for (int i = 0; i < s.nu; ++i) col.push_back(pole(i, j));
    du[size_t(j)] = derivative(col, s.uknots, s.udegree);
    const bool vmeets = meets(s.vknots, size_t(j), s.vdegree, v0, v1);
    if (s.udegree >= 2 && vmeets) {
      const Row duu = derivative(du[size_t(j)], ushift, s.udegree - 1);
      for (size_t i = 0; i < duu.size(); ++i)
        if (meets(s.uknots, i + 2, s.udegree - 2, u0, u1)) m.uu = std::max(m.uu, duu[i].norm());
    }
  }
  // Along v: per row i, the second differences in j.
  for (int i = 0; i < s.nu; ++i) {
    if (s.vdegree < 2 || !meets(s.uknots, size_t(i), s.udegree, u0, u1)) continue;
    Row row;
    for (int j = 0; j < s.nv; ++j) row.push_back(pole(i, j));
    const Row dvv = derivative(derivative(row, s.vknots, s.vdegree), vshift, s.vdegree - 1);
    for (size_t j = 0; j < dvv.size(); ++j)
      if (meets(s.vknots, j + 2, s.vdegree - 2, v0, v1)) m.vv = std::max(m.vv, dvv[j].norm());
  }
  // Mixed: the u-derivative's control points differenced in v.
  if (s.udegree >= 1 && s.vdegree >= 1)
    for (size_t i = 0; i + 1 < size_t(s.nu); ++i) {
      if (!meets(s.uknots, i + 1, s.udegree - 1, u0, u1)) continue;
      Row row;
      for (int j = 0; j < s.nv; ++j) row.push_back(du[size_t(j)][i]);
      const Row duv = derivative(row, s.vknots, s.vdegree);
      for (size_t j = 0; j < duv.size(); ++j)
        if (meets(s.vknots, j + 1, s.vdegree - 1, v0, v1)) m.uv = std::max(m.uv, duv[j].norm());
    }
  return m;
}

}  // namespace pd
