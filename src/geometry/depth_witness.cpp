#include "geometry/depth_witness.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <vector>

#include "geometry/aabb.h"
#include "geometry/frame.h"
#include "tolerances.h"

namespace pd {

namespace {

using Vec2 = Eigen::Vector2d;
using Polygon = std::vector<Vec2>;

double cross(const Vec2& u, const Vec2& v) {
  return u.x() * v.y() - u.y() * v.x();
}

// The convex hull of points in the plane, counter-clockwise (Andrew's monotone
// chain); points within eps of each other are one, collinear ones dropped. One
// point, or the two ends of a segment, when the points span no area.
Polygon hull_2d(Polygon p, double eps) {
  std::sort(p.begin(), p.end(), [](const Vec2& u, const Vec2& v) {
    return u.x() < v.x() || (u.x() == v.x() && u.y() < v.y());
  });
  Polygon h(2 * p.size());
  size_t k = 0;
  const auto turn = [&](size_t floor, const Vec2& q) {
    while (k >= floor + 2 &&
           cross(h[k - 1] - h[k - 2], q - h[k - 2]) <= eps * (h[k - 1] - h[k - 2]).norm())
      --k;
  };
  for (const Vec2& q : p) {
    if (k > 0 && (q - h[k - 1]).norm() <= eps) continue;
    turn(0, q);
    h[k++] = q;
  }
  const size_t lower = k;
  for (size_t i = p.size(); i-- > 0;) {
    if ((p[i] - h[k - 1]).norm() <= eps) continue;
    turn(lower - 1, p[i]);
    h[k++] = p[i];
  }
  if (k > 1 && (h[k - 1] - h[0]).norm() <= eps) --k;  // the chain closed on its start
  h.resize(std::max<size_t>(k, 1));
  return h;
}

// Sutherland–Hodgman: the part of `subject` (any convex polygon, a segment or a
// point) inside the counter-clockwise convex polygon `clip`.
Polygon clip_convex(Polygon subject, const Polygon& clip) {
  for (size_t e = 0; e < clip.size() && !subject.empty(); ++e) {
    const Vec2 &p = clip[e], &q = clip[(e + 1) % clip.size()];
    const auto side = [&](const Vec2& x) { return cross(q - p, x - p); };
    Polygon out;
    for (size_t i = 0; i < subject.size(); ++i) {
      const Vec2 &u = subject[i], &v = subject[(i + 1) % subject.size()];
      const double su = side(u), sv = side(v);
      if (su >= 0) out.push_back(u);
      if ((su < 0) != (sv < 0)) out.push_back(u + (v - u) * (su / (su - sv)));
    }
    subject.swap(out);
  }
  return subject;
}

Vec2 mean(const Polygon& p) {
  Vec2 s = Vec2::Zero();
  for (const Vec2& x : p) s += x;
  return s / double(p.size());
}

// The area centroid, or for a polygon without area the middle of its two
// farthest points (a segment's middle, a point itself).
Vec2 centroid(const Polygon& p, double eps) {
  double area = 0.0;
  Vec2 c = Vec2::Zero();
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec2 &u = p[i], &v = p[(i + 1) % p.size()];
    const double w = cross(u - p[0], v - p[0]);
    area += w;
    c += w * (p[0] + u + v) / 3.0;
  }
  if (area > eps * eps) return c / area;
  Vec2 s = p[0], t = p[0];
  for (const Vec2& u : p)
    for (const Vec2& v : p)
      if ((u - v).squaredNorm() > (s - t).squaredNorm()) s = u, t = v;
  return (s + t) / 2;
}

// The point of segment [p, q] nearest x.
Vec2 nearest_on(const Vec2& x, const Vec2& p, const Vec2& q) {
  const Vec2 u = q - p;
  const double uu = u.squaredNorm();
  return uu == 0 ? p : Vec2(p + u * std::clamp((x - p).dot(u) / uu, 0.0, 1.0));
}

// The middle of two segments' (or points') meeting: their overlap's middle when
// they are collinear, else the middle of their nearest points (their crossing).
Vec2 segments_middle(const Polygon& s, const Polygon& t, double eps) {
  const Vec2 &p = s.front(), &q = s.back(), &r = t.front(), &w = t.back();
  const Vec2 u = q - p, v = w - r;
  if (std::abs(cross(u, v)) <= eps * u.norm() * v.norm() && u.norm() > eps && v.norm() > eps) {
    const Vec2 e = u.normalized();  // parallel: the overlap of their spans along e
    const double lo = std::max(0.0, std::min((r - p).dot(e), (w - p).dot(e)));
    const double hi = std::min(u.norm(), std::max((r - p).dot(e), (w - p).dot(e)));
    if (lo <= hi) {
      const Vec2 off = (r - p) - e * (r - p).dot(e);  // t's offset from s's line
      return p + e * ((lo + hi) / 2) + off / 2;
    }
  }
  // Nearest points: the best of each end against the other segment, and the crossing.
  Vec2 best_a = p, best_b = nearest_on(p, r, w);
  const auto consider = [&](const Vec2& x, const Vec2& y) {
    if ((x - y).squaredNorm() < (best_a - best_b).squaredNorm()) best_a = x, best_b = y;
  };
  consider(q, nearest_on(q, r, w));
  consider(nearest_on(r, p, q), r);
  consider(nearest_on(w, p, q), w);
  const double den = cross(u, v);
  if (den != 0) {
    const double a = cross(r - p, v) / den, b = cross(r - p, u) / den;
    if (a >= 0 && a <= 1 && b >= 0 && b <= 1) best_a = best_b = p + u * a;
  }
  return (best_a + best_b) / 2;
}

// The centroid of the patch where the two faces (projected across d) meet.
Vec2 patch_centre(const Polygon& fa, const Polygon& fb, double eps) {
  if (fa.size() < 3 && fb.size() < 3) return segments_middle(fa, fb, eps);
  const bool a_clips = fa.size() >= 3;
  const Polygon patch = clip_convex(a_clips ? fb : fa, a_clips ? fa : fb);
  // Empty only when d is not the optimal direction (or by rounding): the faces
  // do not meet once b moves out; the middle of their centres then.
  if (patch.empty()) return (mean(fa) + mean(fb)) / 2;
  return centroid(patch, eps);
}

}  // namespace

Vec3 depth_witness(const Points& a_world, const Points& b_world, const Vec3& d) {
  const Frame f = pair_frame(a_world, b_world);
  const Points a = f.to_local(a_world), b = f.to_local(b_world);
  const Eigen::RowVectorXd ha = d.transpose() * a, hb = d.transpose() * b;
  const double top_a = ha.maxCoeff(), bottom_b = hb.minCoeff();
  const double eps = tol::kWitnessFace;
  const Vec3 e1 = d.unitOrthogonal(), e2 = d.cross(e1);
  Polygon fa, fb;
  for (Eigen::Index k = 0; k < a.cols(); ++k)
    if (ha[k] >= top_a - eps) fa.emplace_back(e1.dot(a.col(k)), e2.dot(a.col(k)));
  for (Eigen::Index k = 0; k < b.cols(); ++k)
    if (hb[k] <= bottom_b + eps) fb.emplace_back(e1.dot(b.col(k)), e2.dot(b.col(k)));
  const Vec2 c = patch_centre(hull_2d(fa, eps), hull_2d(fb, eps), eps);
  const Vec3 local = e1 * c.x() + e2 * c.y() + d * ((top_a + bottom_b) / 2);
  Vec3 w = local * f.scale + f.centre;
  if (top_a > bottom_b) {  // overlapping: within the region both boxes hold
    const Aabb ba = Aabb::of(a_world), bb = Aabb::of(b_world);
    for (int i = 0; i < 3; ++i) {
      const double lo = std::max(ba.lo[i], bb.lo[i]), hi = std::min(ba.hi[i], bb.hi[i]);
      w[i] = lo <= hi ? std::clamp(w[i], lo, hi) : (lo + hi) / 2;
    }
  }
  return w;
}

}  // namespace pd
