#include "solve/gjk.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tolerances.h"

namespace pd {

namespace {

// The simplex: up to four support points of D.
struct Simplex {
  std::array<Vec3, 4> x;
  std::array<MinkowskiIndex, 4> id;  // where each point came from (for EPA's exact step)
  int size = 0;
};

// The face of s without vertex k.
Simplex without(const Simplex& s, int k) {
  Simplex f;
  for (int i = 0; i < s.size; ++i)
    if (i != k) {
      f.id[f.size] = s.id[i];
      f.x[f.size++] = s.x[i];
    }
  return f;
}

// A tetrahedron holds the origin when no face has it beyond its plane (on the
// side away from the opposite vertex) by more than the rounding. So the origin
// on a face or an edge counts as held (EPA's start lifts such faces), and a
// tetrahedron flat to rounding holds nothing.
bool holds_origin(const Simplex& s) {
  for (int k = 0; k < 4; ++k) {
    const Simplex f = without(s, k);
    const Vec3 n = (f.x[1] - f.x[0]).cross(f.x[2] - f.x[0]);
    const double slack = tol::kEpaRounding * n.norm();
    const double apex = n.dot(s.x[k] - f.x[0]), origin = -n.dot(f.x[0]);
    if (!(std::abs(apex) > slack)) return false;
    if ((apex > 0 ? -origin : origin) > slack) return false;
  }
  return true;
}

Vec3 nearest(Simplex& s);

// The nearest point to the origin over the faces of s (a segment's ends, a
// triangle's edges, a tetrahedron's triangles), s reduced to the face holding
// it: the nearest point of s whenever the origin's projection falls outside s.
Vec3 nearest_on_faces(Simplex& s) {
  Vec3 best_x = Vec3::Zero();
  double best = std::numeric_limits<double>::infinity();
  Simplex best_face;
  for (int k = 0; k < s.size; ++k) {
    Simplex f = without(s, k);
    const Vec3 x = nearest(f);
    if (x.squaredNorm() < best) {
      best = x.squaredNorm();
      best_x = x;
      best_face = f;
    }
  }
  s = best_face;
  return best_x;
}

// The point of s nearest the origin; s is reduced to the smallest face holding
// it, and keeps all four vertices only when it holds the origin (then 0).
Vec3 nearest(Simplex& s) {
  if (s.size == 1) return s.x[0];
  if (s.size == 2) {
    const Vec3 a = s.x[0], ab = s.x[1] - a;
    const double t = -a.dot(ab), len2 = ab.squaredNorm();
    if (t > 0 && t < len2) return a + (t / len2) * ab;
  } else if (s.size == 3) {
    const Vec3 &a = s.x[0], &b = s.x[1], &c = s.x[2];
    const Vec3 n = (b - a).cross(c - a);
    // The barycentric weights of the origin's projection on the plane (|n|²
    // times): all positive, it lies inside and is the nearest point.
    if (n.dot(b.cross(c)) > 0 && n.dot(c.cross(a)) > 0 && n.dot(a.cross(b)) > 0)
      return n * (n.dot(a) / n.squaredNorm());
  } else if (holds_origin(s)) {
    return Vec3::Zero();
  }
  return nearest_on_faces(s);
}

// A unit direction off the span of s (1 to 3 points): a triangle's normal, a
// segment's perpendicular; zero when s is degenerate.
Vec3 off_span(const Simplex& s) {
  const Vec3 e = s.x[1] - s.x[0];
  const Vec3 d = s.size == 3 ? e.cross(s.x[2] - s.x[0]) : e.unitOrthogonal();
  const double len = d.norm();
  return len > 0 ? Vec3(d / len) : Vec3(Vec3::Zero());
}

class Search {
 public:
  Search(const PairProblem& pr, int budget) : pr_(pr), budget_(budget) {
    r_.gap = std::numeric_limits<double>::infinity();
  }

  GjkResult run() {
    // A point of D inside it (difference of the vertex means); search towards
    // the origin from there.
    const Vec3 inner = pr_.p().rowwise().mean() - pr_.q().rowwise().mean();
    Vec3 d = inner.squaredNorm() > 0 ? Vec3(-inner) : Vec3(Vec3::UnitX());
    double last = std::numeric_limits<double>::infinity();  // |nearest|² of the simplex
    Vec3 w;
    MinkowskiIndex id;
    while (probe(d.normalized(), w, id)) {
      if (std::find(s_.x.begin(), s_.x.begin() + s_.size, w) != s_.x.begin() + s_.size)
        return r_;  // no new point: the origin is on D's boundary (to rounding)
      s_.id[s_.size] = id;
      s_.x[s_.size++] = w;
      const Vec3 x = nearest(s_);
      if (s_.size == 4) return enclosed();
      const double dist = x.norm();
      r_.lower = std::max(r_.lower, -dist - tol::kEpaRounding);
      if (dist <= tol::kEpaRounding) return complete();
      // No progress towards the origin (to rounding): it lies on D's boundary.
      if (!(dist * dist < last)) return r_;
      last = dist * dist;
      d = -x;
    }
    return r_;
  }

 private:
  // Evaluates the support in unit v into w, keeping the lowest gap. False when
  // the search is over: v separates (gap <= 0), or the budget is spent.
  bool probe(const Vec3& v, Vec3& w, MinkowskiIndex& id) {
    if (evaluations_++ >= budget_) return false;
    const double g = pr_.support(v, w, id);
    if (g < r_.gap) {
      r_.gap = g;
      r_.direction = v;
    }
    if (g > 0) return true;
    r_.outcome = GjkResult::Outcome::kSeparated;
    return false;
  }

  GjkResult enclosed() {
    r_.outcome = GjkResult::Outcome::kEnclosed;
    r_.tetrahedron = s_.x;
    r_.tetrahedron_ids = s_.id;
    return r_;
  }

  // The origin lies on the simplex to rounding. Each step adds the support
  // point off its span; one beyond the simplex by more than the rounding keeps
  // the origin on the grown simplex, which ends as a tetrahedron holding it. A
  // direction with nothing beyond is a supporting plane of D through the
  // origin (its gap is about 0, kept in r_): the pair touches.
  GjkResult complete() {
    Vec3 w;
    MinkowskiIndex id;
    while (s_.size < 4) {
      if (s_.size == 1) return r_;  // a support point at the origin: gap(v) = v·w ≈ 0
      const Vec3 v = off_span(s_);
      if (v == Vec3::Zero() || !probe(v, w, id)) return r_;
      if (!(v.dot(w) > v.dot(s_.x[0]) + tol::kEpaRounding)) return r_;
      s_.id[s_.size] = id;
      s_.x[s_.size++] = w;
    }
    return enclosed();
  }

  const PairProblem& pr_;
  const int budget_;
  int evaluations_ = 0;
  Simplex s_;
  GjkResult r_;
};

}  // namespace

GjkResult gjk_enclose_origin(const PairProblem& pr, int max_iterations) {
  return Search(pr, max_iterations).run();
}

}  // namespace pd
