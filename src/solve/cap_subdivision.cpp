#include "solve/cap_subdivision.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "solve/objective.h"
#include "tolerances.h"

namespace pd {

namespace {

// A square [s0, s1] × [t0, t1] of the gnomonic plane, with the vertices that can
// be extreme in a cap (`valid_centre`, `valid_radius`) holding the square.
struct Cell {
  double s0, s1, t0, t1;
  std::vector<int> pi, qj;
  Vec3 valid_centre;
  double valid_radius;
  Vec3 parent_point;  // the parent's support point: a point of P − Q, a bound too
};

}  // namespace

SubdividedSearch lowest_facet_subdivided(const Points& p, const Points& q, const Vec3& centre,
                                         double radius, double best, long leaf_points,
                                         long max_cells, double settle_at) {
  SubdividedSearch out;
  const Vec3 helper = std::abs(centre.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 e1 = centre.cross(helper).normalized(), e2 = centre.cross(e1);
  auto dir = [&](double s, double t) { return (centre + s * e1 + t * e2).normalized(); };
  auto slack = [](double g) { return g + 1e-12 * std::max(1.0, std::abs(g)); };
  double lowest = slack(best);
  // Cells close against the lowest gap known, not only against `best`: every
  // cell centre's gap is a real direction's, so the global minimum is at or below
  // it and its cell never closes. Near a resting contact the centres' gaps fall
  // to the minimum long before a leaf's hull finds its facet, so most cells of
  // the cap close at their first bound.
  double prune = lowest;
  out.witness_gap = std::numeric_limits<double>::infinity();

  // The root square holds the cap (its gnomonic image is a disc of radius tan r).
  const double half = std::tan(radius);
  Cell root{-half,       half,
            -half,       half,
            {},          {},
            centre,      tol::kSubdivisionValidMargin * std::atan(half * std::sqrt(2.0)) * 1.001,
            Vec3::Zero()};
  root.pi = extreme_in_cap(p, centre, root.valid_radius, true);
  root.qj = extreme_in_cap(q, centre, root.valid_radius, false);
  std::vector<Cell> stack;
  stack.push_back(std::move(root));
  const double cos_cap = std::cos(radius);
  while (!stack.empty()) {
    Cell c = std::move(stack.back());
    stack.pop_back();
    if (++out.cells > max_cells) {
      out.result.searched = false;
      out.result.lowest.reset();
      return out;
    }
    const double sm = 0.5 * (c.s0 + c.s1), tm = 0.5 * (c.t0 + c.t1);
    const Vec3 mid = dir(sm, tm);
    const Vec3 corners[4] = {dir(c.s0, c.t0), dir(c.s1, c.t0), dir(c.s1, c.t1), dir(c.s0, c.t1)};
    double rho = 0;
    for (const Vec3& k : corners) rho = std::max(rho, angle_between(mid, k));
    rho *= 1 + tol::kCellRadiusPad;
    // Outside the cap: nothing to search (other cells of the certificate cover it).
    if (mid.dot(centre) < cos_cap && angle_between(mid, centre) - rho > radius) continue;
    // The support point at the centre, over the candidates (exact: they hold
    // every vertex extreme in the cell's valid cap, which holds the cell).
    int ip = c.pi.front(), iq = c.qj.front();
    double hp = -std::numeric_limits<double>::infinity(), hq = -hp;
    for (int i : c.pi)
      if (const double s = mid.dot(p.col(i)); s > hp) hp = s, ip = i;
    for (int j : c.qj)
      if (const double s = mid.dot(q.col(j)); s < hq) hq = s, iq = j;
    const Vec3 x = p.col(ip) - q.col(iq);
    if (hp - hq < out.witness_gap) {
      out.witness_gap = hp - hq;
      out.witness = mid;
      prune = std::min(prune, slack(hp - hq));
      // A resting contact: every vertex of both touching faces is extreme at its
      // normal, so the cells around it never shrink to a small hull; a centre
      // within contact resolution of the minimum decides the pair already.
      if (hp - hq <= settle_at) return out;
    }
    // min over the cell of x·u: at a corner when all corners are positive.
    auto bound = [&](const Vec3& y) {
      double lo = std::numeric_limits<double>::infinity();
      for (const Vec3& k : corners) lo = std::min(lo, y.dot(k));
      return lo > 0 ? lo : -1.0;
    };
    if (std::max(bound(x), bound(c.parent_point)) > prune) continue;  // closed
    // Open: the cell's own candidates (within its parent's, a larger cap).
    const double vr = tol::kSubdivisionValidMargin * rho;
    if (angle_between(mid, c.valid_centre) + vr > c.valid_radius) {
      c.pi = extreme_in_cap(p, mid, vr, true);  // not nested (never expected): from scratch
      c.qj = extreme_in_cap(q, mid, vr, false);
    } else {
      c.pi = extreme_in_cap_among(p, c.pi, mid, vr, true);
      c.qj = extreme_in_cap_among(q, c.qj, mid, vr, false);
    }
    if (long(c.pi.size()) * long(c.qj.size()) <= leaf_points) {
      // Exactly P − Q's facets with normals in the valid cap; the cell is in it.
      if (const auto f = lowest_local_facet(p, q, c.pi, c.qj, mid, vr); f && f->offset < lowest) {
        lowest = f->offset;
        prune = std::min(prune, slack(f->offset));
        out.result.lowest = *f;
      }
      continue;
    }
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        Cell child{
            a ? sm : c.s0, a ? c.s1 : sm, b ? tm : c.t0, b ? c.t1 : tm, c.pi, c.qj, mid, vr, x};
        stack.push_back(std::move(child));
      }
  }
  return out;
}

}  // namespace pd
