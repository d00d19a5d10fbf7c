#include "solve/exact_facet.h"

#include <gmpxx.h>

#include <cmath>

namespace pd {

namespace {

struct QVec {
  mpq_class x, y, z;
};

QVec operator-(const QVec& u, const QVec& v) {
  return {u.x - v.x, u.y - v.y, u.z - v.z};
}
mpq_class dot(const QVec& u, const QVec& v) {
  return u.x * v.x + u.y * v.y + u.z * v.z;
}
QVec cross(const QVec& u, const QVec& v) {
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}
// A column of the input, exactly (a double is a dyadic rational).
QVec column(const Points& x, int k) {
  return {mpq_class(x(0, k)), mpq_class(x(1, k)), mpq_class(x(2, k))};
}

struct Plane {
  QVec n;           // outward normal (x1 − x0) × (x2 − x0)
  mpq_class d;      // offset n·x0: the origin is inside when d > 0
  mpq_class dist2;  // squared distance of the origin, d² / |n|²
};

// The extreme of n·x over the columns of x (largest when top), exactly. A
// double pass finds the candidates: the rounded unit normal's dot products are
// within ~2e-15 of the exact ones (times the largest coordinate), so the exact
// extreme lies within twice that of the double one; the band is 50 times wider.
mpq_class exact_extreme(const Points& x, const QVec& n, const Vec3& unit, double size, bool top) {
  const Eigen::RowVectorXd s = unit.transpose() * x;
  const double e = top ? s.maxCoeff() : s.minCoeff();
  const double band = 1e-13 * size;
  mpq_class best;
  bool first = true;
  for (Eigen::Index k = 0; k < s.size(); ++k) {
    if (top ? s[k] < e - band : s[k] > e + band) continue;
    const mpq_class v = dot(n, column(x, static_cast<int>(k)));
    if (first || (top ? v > best : v < best)) best = v;
    first = false;
  }
  return best;
}

Vec3 rounded_unit(const QVec& n) {
  const Vec3 v(n.x.get_d(), n.y.get_d(), n.z.get_d());
  return v.normalized();
}

// The plane supports P − Q: max a·n − min b·n is its offset (never less, as
// the plane holds points of P − Q).
bool supports(const Points& a, const Points& b, const Plane& pl) {
  const Vec3 unit = rounded_unit(pl.n);
  const double size = std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff());
  return exact_extreme(a, pl.n, unit, size, true) - exact_extreme(b, pl.n, unit, size, false) <=
         pl.d;
}

}  // namespace

std::optional<ExactFacet> exact_facet_depth(const Points& a, const Points& b,
                                            const std::vector<std::array<MinkowskiIndex, 3>>& faces,
                                            double bound) {
  if (faces.empty()) return std::nullopt;
  std::vector<Plane> planes;
  planes.reserve(faces.size());
  for (const auto& f : faces) {
    std::array<QVec, 3> x;
    for (int k = 0; k < 3; ++k) x[k] = column(a, f[k].i) - column(b, f[k].j);
    Plane pl;
    pl.n = cross(x[1] - x[0], x[2] - x[0]);
    pl.d = dot(pl.n, x[0]);
    if (sgn(pl.d) <= 0) return std::nullopt;  // the origin is on or behind it
    pl.dist2 = pl.d * pl.d / dot(pl.n, pl.n);
    planes.push_back(std::move(pl));
  }
  const Plane* nearest = &planes[0];
  for (const Plane& pl : planes)
    if (pl.dist2 < nearest->dist2) nearest = &pl;
  // The nearest distance is the lower bound; a plane at that distance that
  // supports P − Q attains it (several: the triangles of one facet).
  for (const Plane& pl : planes) {
    if (pl.dist2 != nearest->dist2 || !supports(a, b, pl)) continue;
    ExactFacet out;
    out.depth = std::sqrt(pl.dist2.get_d());
    if (!(out.depth <= bound)) return std::nullopt;
    out.direction = rounded_unit(pl.n);
    return out;
  }
  return std::nullopt;
}

}  // namespace pd
