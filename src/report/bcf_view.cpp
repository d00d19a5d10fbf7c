#include "report/bcf_view.h"

#include <algorithm>
#include <cmath>

#include "tolerances.h"

namespace pd {

namespace {

double half_diagonal(const Aabb& b) {
  return 0.5 * (b.hi - b.lo).norm();
}

Vec3 centre(const Aabb& b) {
  return 0.5 * (b.lo + b.hi);
}

/// `v` without its component along unit `n`, normalised; nullopt when `v` is
/// (nearly) along `n`.
std::optional<Vec3> across(const Vec3& v, const Vec3& n) {
  const Vec3 w = v - v.dot(n) * n;
  const double len = w.norm();
  if (len < tol::kBcfAcross * v.norm()) return std::nullopt;
  return w / len;
}

}  // namespace

ViewTarget view_target(const std::optional<Vec3>& at, const std::optional<Aabb>& a,
                       const std::optional<Aabb>& b) {
  ViewTarget t;
  if (!a && !b) {
    if (at) t.centre = *at;
    t.at = at.has_value();
    return t;
  }
  const Aabb& small = !b || (a && half_diagonal(*a) <= half_diagonal(*b)) ? *a : *b;
  t.radius = half_diagonal(small);
  if (at) {
    t.centre = *at;
    t.at = true;
  } else if (a && b && a->overlaps(*b)) {
    t.centre = 0.5 * (a->lo.cwiseMax(b->lo) + a->hi.cwiseMin(b->hi));
  } else if (a && b) {
    t.centre = 0.5 * (centre(*a) + centre(*b));
    t.radius = std::max(t.radius, 0.5 * (centre(*a) - centre(*b)).norm());
  } else {
    t.centre = centre(small);
  }
  if (!(t.radius > 0.0))  // a flat or point-like smaller part: the other one
    t.radius = std::max(a ? half_diagonal(*a) : 0.0, b ? half_diagonal(*b) : 0.0);
  if (!(t.radius > 0.0) || !std::isfinite(t.radius)) t.radius = 1.0;
  return t;
}

PerspectiveCamera camera_on(const ViewTarget& t, const Vec3& depth_direction) {
  Vec3 n = depth_direction;
  n = n.norm() > 0.0 && n.allFinite() ? Vec3(n.normalized()) : Vec3::UnitZ();
  const Vec3 iso = Vec3(1.0, 1.0, -1.0).normalized();
  std::optional<Vec3> d = across(iso, n);
  if (!d) d = across(Vec3(1.0, -1.0, -1.0).normalized(), n);  // n near iso: the other diagonal
  std::optional<Vec3> up = across(Vec3::UnitZ(), *d);
  if (!up) up = across(Vec3::UnitY(), *d);  // looking straight down or up
  PerspectiveCamera c;
  c.direction = *d;
  c.up = *up;
  c.field_of_view = tol::kBcfFieldOfView;
  c.aspect_ratio = tol::kBcfAspectRatio;
  const double half = tol::kBcfFieldOfView * M_PI / 360.0;
  c.viewpoint = t.centre - (t.radius / std::sin(half)) * c.direction;
  return c;
}

}  // namespace pd
