#include "solve/gjk.h"

#include <algorithm>
#include <limits>

namespace pd {

namespace {

// The simplex: up to four support points; `closest` reduces it to the smallest
// face holding the point of its hull nearest the origin and returns that point.
struct Simplex {
  std::array<Vec3, 4> x;
  int size = 0;
};

// Nearest point to the origin on segment ab; keeps the vertices it needs.
Vec3 closest_segment(Simplex& s) {
  const Vec3 a = s.x[0], b = s.x[1], ab = b - a;
  const double t = -a.dot(ab);
  if (t <= 0) {
    s.size = 1;
    return a;
  }
  const double len2 = ab.squaredNorm();
  if (t >= len2) {
    s.x[0] = b;
    s.size = 1;
    return b;
  }
  return a + (t / len2) * ab;
}

// Nearest point to the origin on triangle abc (Ericson, Real-Time Collision
// Detection, 5.1.5), keeping the vertices of the feature it lies on.
Vec3 closest_triangle(Simplex& s) {
  const Vec3 a = s.x[0], b = s.x[1], c = s.x[2];
  const Vec3 ab = b - a, ac = c - a;
  const double d1 = -ab.dot(a), d2 = -ac.dot(a);
  if (d1 <= 0 && d2 <= 0) {
    s.size = 1;
    return a;
  }
  const double d3 = -ab.dot(b), d4 = -ac.dot(b);
  if (d3 >= 0 && d4 <= d3) {
    s.x[0] = b;
    s.size = 1;
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    s.size = 2;
    return a + (d1 / (d1 - d3)) * ab;
  }
  const double d5 = -ab.dot(c), d6 = -ac.dot(c);
  if (d6 >= 0 && d5 <= d6) {
    s.x[0] = c;
    s.size = 1;
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    s.x[1] = c;
    s.size = 2;
    return a + (d2 / (d2 - d6)) * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    s.x[0] = b;
    s.x[1] = c;
    s.size = 2;
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  }
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// Tetrahedron abcd: the origin is inside when it lies on the inner side of
// every face (an undecided sign counts as outside, so a flat tetrahedron is
// never taken to enclose it); else the nearest point over the faces it lies
// outside of. Returns true when enclosed.
bool closest_tetrahedron(Simplex& s, Vec3& closest) {
  static constexpr int kFace[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
  double best = std::numeric_limits<double>::infinity();
  Simplex best_face;
  bool outside_any = false;
  for (const auto& f : kFace) {
    const Vec3 &a = s.x[f[0]], &b = s.x[f[1]], &c = s.x[f[2]], &d = s.x[f[3]];
    const Vec3 n = (b - a).cross(c - a);
    const double side_origin = -n.dot(a), side_d = n.dot(d - a);
    if (side_origin * side_d > 0) continue;  // the origin is on d's side of this face
    outside_any = true;
    Simplex t;
    t.x = {a, b, c, Vec3::Zero()};
    t.size = 3;
    const Vec3 x = closest_triangle(t);
    if (x.squaredNorm() < best) {
      best = x.squaredNorm();
      closest = x;
      best_face = t;
    }
  }
  if (!outside_any) return true;
  s = best_face;
  return false;
}

}  // namespace

GjkResult gjk_enclose_origin(const PairProblem& pr, int max_iterations) {
  GjkResult r;
  r.gap = std::numeric_limits<double>::infinity();
  // A point of D inside it (difference of the vertex means); search towards
  // the origin from there.
  const Vec3 inner = pr.p().rowwise().mean() - pr.q().rowwise().mean();
  Vec3 d = inner.squaredNorm() > 0 ? Vec3(-inner) : Vec3(Vec3::UnitX());
  Simplex s;
  double last = std::numeric_limits<double>::infinity();  // |closest|² of the simplex
  for (int it = 0; it < max_iterations; ++it) {
    const Vec3 v = d.normalized();
    Vec3 w;
    const double g = pr.support(v, w);
    if (g < r.gap) {
      r.gap = g;
      r.direction = v;
    }
    if (g <= 0) {  // D lies where x·v <= 0: the origin is not inside
      r.outcome = GjkResult::Outcome::kSeparated;
      return r;
    }
    for (int k = 0; k < s.size; ++k)
      if (s.x[k] == w) return r;  // no new point: the origin is on D's boundary
    s.x[s.size++] = w;
    Vec3 x;
    if (s.size == 1) {
      x = w;
    } else if (s.size == 2) {
      x = closest_segment(s);
    } else if (s.size == 3) {
      x = closest_triangle(s);
    } else if (closest_tetrahedron(s, x)) {
      r.outcome = GjkResult::Outcome::kEnclosed;
      r.tetrahedron = s.x;
      return r;
    }
    const double dist2 = x.squaredNorm();
    if (dist2 == 0 && s.size >= 2) {
      // The origin on the segment or in the triangle's plane (symmetric pairs):
      // look off it for the next point.
      const Vec3 e = s.x[1] - s.x[0];
      d = s.size == 3 ? e.cross(s.x[2] - s.x[0]) : e.cross(e.unitOrthogonal());
      if (d.squaredNorm() == 0) return r;
      continue;
    }
    // No progress towards the origin (to rounding): it lies on D's boundary.
    if (!(dist2 < last) || dist2 == 0) return r;
    last = dist2;
    d = -x;
  }
  return r;
}

}  // namespace pd
