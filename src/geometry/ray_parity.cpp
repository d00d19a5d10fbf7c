#include "geometry/ray_parity.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace pd {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = K::Point_3;

Point3 point(const Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

enum class Hit { kMiss, kCross, kOnSurface, kUndecided };

// How the segment from p to e (e outside the soup's box, so on no triangle)
// meets triangle t: crosses its interior, misses it, starts on it, or touches
// an edge, a vertex or its plane, where parity proves nothing.
Hit classify(const Point3& p, const Point3& e, const std::array<Vec3, 3>& t) {
  const Point3 a = point(t[0]), b = point(t[1]), c = point(t[2]);
  const CGAL::Orientation op = CGAL::orientation(a, b, c, p), oe = CGAL::orientation(a, b, c, e);
  if (op == CGAL::COPLANAR) {
    if (K::Triangle_3(a, b, c).has_on(p)) return Hit::kOnSurface;
    // In the plane, beside the triangle: the segment runs in the plane (and
    // may graze it) or leaves the plane at once.
    if (oe != CGAL::COPLANAR) return Hit::kMiss;
    return CGAL::do_intersect(K::Triangle_3(a, b, c), K::Segment_3(p, e)) ? Hit::kUndecided
                                                                          : Hit::kMiss;
  }
  // e meets the plane only at e, which lies on no triangle.
  if (oe == CGAL::COPLANAR || oe == op) return Hit::kMiss;
  // p and e on opposite sides: the line p–e passes inside the triangle when
  // it turns the same way about each edge.
  const CGAL::Orientation s0 = CGAL::orientation(p, e, a, b), s1 = CGAL::orientation(p, e, b, c),
                          s2 = CGAL::orientation(p, e, c, a);
  const bool none_negative = s0 >= 0 && s1 >= 0 && s2 >= 0,
             none_positive = s0 <= 0 && s1 <= 0 && s2 <= 0;
  if (!none_negative && !none_positive) return Hit::kMiss;
  if (s0 == CGAL::COPLANAR || s1 == CGAL::COPLANAR || s2 == CGAL::COPLANAR)
    return Hit::kUndecided;  // through an edge or a vertex
  return Hit::kCross;
}

// The sign of the 2D orientation of (a, b, q): exact. CAD coordinates are
// often aligned (an edge parallel to an axis, a point level with it), and
// there the determinant is exactly zero, which CGAL's filters cannot certify
// and hand to exact rational arithmetic: the aligned cases are settled first
// by comparisons, which are exact.
int orient2(double au, double av, double bu, double bv, double qu, double qv) {
  const auto sign = [](double x) { return (x > 0) - (x < 0); };
  if (au == bu) return -sign(bv - av) * sign(qu - au);
  if (av == bv) return sign(bu - au) * sign(qv - av);
  // Shewchuk's first stage (orient2d, "Adaptive Precision Floating-Point
  // Arithmetic and Fast Robust Geometric Predicates", 1997): the products'
  // signs, or the determinant beyond his error bound, are certain. Inline, it
  // costs a fraction of the call into CGAL's filter, which the rest goes to.
  const double left = (au - qu) * (bv - qv), right = (av - qv) * (bu - qu);
  if (left > 0 && right < 0) return 1;
  if (left < 0 && right > 0) return -1;
  constexpr double kBound = 3.3306690738754716e-16;  // (3 + 16ε)ε, ε = 2^-53
  const double det = left - right, bound = kBound * (std::abs(left) + std::abs(right));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return static_cast<int>(
      CGAL::orientation(K::Point_2(au, av), K::Point_2(bu, bv), K::Point_2(qu, qv)));
}

// How the ray from p along axis k (towards +k when `up`, else −k) meets
// triangle t, by projecting along the axis as CGAL's vertical ray test does.
// (u, v, k) is a cyclic order of (x, y, z), so the projected triangle's
// orientation is the sign of its normal's k component.
Hit axis_hit(const Vec3& p, int k, bool up, const std::array<Vec3, 3>& t) {
  // Wholly behind p (the tree's box test is padded): exact comparisons.
  const auto behind = [&](const Vec3& c) { return up ? c[k] < p[k] : c[k] > p[k]; };
  if (behind(t[0]) && behind(t[1]) && behind(t[2])) return Hit::kMiss;
  const int u = (k + 1) % 3, v = (k + 2) % 3;
  int order[3] = {0, 1, 2};
  const auto o2 = [&](int i, int j, double qu, double qv) {
    return orient2(t[order[i]][u], t[order[i]][v], t[order[j]][u], t[order[j]][v], qu, qv);
  };
  int turn = o2(0, 1, t[2][u], t[2][v]);
  if (turn == 0) {
    // A face parallel to the axis: its projection is a segment. The ray can
    // meet it only by running in its plane, where parity proves nothing.
    int i = 0, j = 1;  // two corners that project apart
    if (t[0][u] == t[1][u] && t[0][v] == t[1][v]) j = 2;
    if (o2(i, j, p[u], p[v]) != 0) return Hit::kMiss;
    if (K::Triangle_3(point(t[0]), point(t[1]), point(t[2])).has_on(point(p)))
      return Hit::kOnSurface;
    return Hit::kUndecided;  // conservative: the ray may run along the face
  }
  if (turn < 0) std::swap(order[1], order[2]);
  const int e0 = o2(0, 1, p[u], p[v]), e1 = o2(1, 2, p[u], p[v]), e2 = o2(2, 0, p[u], p[v]);
  if (e0 < 0 || e1 < 0 || e2 < 0) return Hit::kMiss;  // the line passes beside it
  // Which side of the face's plane p lies on (the normal's k component is
  // positive now): a face square to the axis by comparison, else exactly.
  const Vec3 &a = t[order[0]], &b = t[order[1]], &c = t[order[2]];
  int side;
  if (a[k] == b[k] && b[k] == c[k])
    side = (p[k] > a[k]) - (p[k] < a[k]);
  else
    side = static_cast<int>(CGAL::orientation(point(a), point(b), point(c), point(p)));
  if (side == 0) return Hit::kOnSurface;  // in the plane, within the projection
  // The line meets the plane ahead of p when p lies on the side the ray leaves.
  if ((side < 0) != up) return Hit::kMiss;
  if (e0 == 0 || e1 == 0 || e2 == 0) return Hit::kUndecided;  // through an edge or a vertex
  return Hit::kCross;
}

// One ray's tally for each soup: the parity of its crossings, whether p lies
// on the soup, and whether the ray met one of its edges, vertices or planes
// (then only a soup p lies on is decided by this ray).
struct Tally {
  bool odd = false, on_surface = false, undecided = false;
};

// Tallies the ray from p to e into `tally` (by the triangle's label; all 0
// without labels). A single soup stops at the first triangle p lies on.
template <class Classify>
void count_along(const TriangleTree& tree, const Vec3& p, const Vec3& e, const int* label,
                 Tally* tally, size_t soups, const Classify& classify) {
  for (size_t i = 0; i < soups; ++i) tally[i].odd = tally[i].undecided = false;
  tree.along_segment(p, e, [&](int id, const std::array<Vec3, 3>& t) {
    Tally& s = tally[label ? label[id] : 0];
    const Hit h = classify(t);
    s.odd = s.odd != (h == Hit::kCross);
    s.undecided = s.undecided || h == Hit::kUndecided;
    s.on_surface = s.on_surface || h == Hit::kOnSurface;
    return !label && s.on_surface;
  });
}

// Far enough past the box [lo, hi] that rounding cannot bring a ray's end
// back into it.
double reach(const Vec3& lo, const Vec3& hi) {
  return 1 + (hi - lo).norm() + hi.cwiseAbs().maxCoeff() + lo.cwiseAbs().maxCoeff();
}

// Tallies the ray from p along `direction` (nonzero) to past the box: by
// projection along an axis direction, else with the general segment test.
void count_ray(const TriangleTree& tree, const int* label, double far, const Vec3& p,
               const Vec3& direction, Tally* tally, size_t soups) {
  const int moving = (direction.x() != 0) + (direction.y() != 0) + (direction.z() != 0);
  if (moving == 1) {
    const int k = direction.x() != 0 ? 0 : direction.y() != 0 ? 1 : 2;
    const bool up = direction[k] > 0;
    Vec3 e = p;
    e[k] += up ? far : -far;
    count_along(tree, p, e, label, tally, soups,
                [&](const std::array<Vec3, 3>& t) { return axis_hit(p, k, up, t); });
    return;
  }
  // Scaled by a power of two, the end is p + direction exactly scaled where
  // the coordinates allow: the ray a caller names is the ray counted.
  const Vec3 e =
      p + std::ldexp(1.0, std::ilogb(far / direction.cwiseAbs().maxCoeff()) + 1) * direction;
  const Point3 pp = point(p), pe = point(e);
  count_along(tree, p, e, label, tally, soups,
              [&](const std::array<Vec3, 3>& t) { return classify(pp, pe, t); });
}

// Rays from p until every soup is decided: the six axis directions, the
// shortest way out of the box [lo, hi] first (it pierces the fewest boxes of
// the tree), then oblique ones in a fixed sequence (results must not depend on
// the run): directions of the golden-angle spiral, which no grid of CAD
// coordinates lines up with.
void tally_rays(const TriangleTree& tree, const int* label, const Vec3& lo, const Vec3& hi,
                const Vec3& p, Tally* tally, size_t soups) {
  const auto decided = [&] {
    return std::all_of(tally, tally + soups,
                       [](const Tally& t) { return t.on_surface || !t.undecided; });
  };
  const double far = reach(lo, hi);
  std::array<std::pair<double, int>, 6> axes;
  for (int k = 0; k < 3; ++k) {
    axes[2 * k] = {hi[k] - p[k], 2 * k};
    axes[2 * k + 1] = {p[k] - lo[k], 2 * k + 1};
  }
  std::sort(axes.begin(), axes.end());
  for (const auto& [gap, code] : axes) {
    (void)gap;
    count_ray(tree, label, far, p, (code % 2 == 0 ? 1.0 : -1.0) * Vec3::Unit(code / 2), tally,
              soups);
    if (decided()) return;
  }
  for (int i = 0;; ++i) {
    const double z = 1 - (2 * (i % 64) + 1) / 64.0, r = std::sqrt(1 - z * z);
    const double angle = 2.399963229728653 * i + 0.1;
    count_ray(tree, label, far, p, Vec3(r * std::cos(angle), r * std::sin(angle), z), tally, soups);
    if (decided()) return;
  }
}

RaySide side_of(const Tally& t) {
  if (t.on_surface) return RaySide::kOnSurface;
  return t.odd ? RaySide::kInside : RaySide::kOutside;
}

bool outside_box(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  for (int k = 0; k < 3; ++k)
    if (p[k] < lo[k] || p[k] > hi[k]) return true;
  return false;
}

}  // namespace

RaySide ray_parity_side(const TriangleTree& tree, const Vec3& lo, const Vec3& hi, const Vec3& p) {
  if (outside_box(p, lo, hi)) return RaySide::kOutside;
  Tally one;
  tally_rays(tree, nullptr, lo, hi, p, &one, 1);
  return side_of(one);
}

void ray_parity_sides(const TriangleTree& tree, const std::vector<int>& label, const Vec3& lo,
                      const Vec3& hi, const Vec3& p, RaySide* sides, size_t soups) {
  if (outside_box(p, lo, hi)) {
    std::fill(sides, sides + soups, RaySide::kOutside);
    return;
  }
  // On the stack for the few shells of a multi-body part (no allocation per test).
  std::array<Tally, 16> few;
  std::vector<Tally> many(soups > few.size() ? soups : 0);
  Tally* tally = soups > few.size() ? many.data() : few.data();
  tally_rays(tree, label.data(), lo, hi, p, tally, soups);
  std::transform(tally, tally + soups, sides, side_of);
}

std::optional<RaySide> ray_parity_along(const TriangleTree& tree, const Vec3& lo, const Vec3& hi,
                                        const Vec3& p, const Vec3& direction) {
  if (outside_box(p, lo, hi)) return RaySide::kOutside;
  Tally one;
  count_ray(tree, nullptr, reach(lo, hi), p, direction, &one, 1);
  if (!one.on_surface && one.undecided) return std::nullopt;
  return side_of(one);
}

bool segment_meets_triangles(const TriangleTree& tree, const Vec3& a, const Vec3& b) {
  const K::Segment_3 s(point(a), point(b));
  return tree.along_segment(a, b, [&](int, const std::array<Vec3, 3>& t) {
    return CGAL::do_intersect(K::Triangle_3(point(t[0]), point(t[1]), point(t[2])), s);
  });
}

}  // namespace pd
