#include "solve/neighbourhood.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>

#include "geometry/hull.h"
#include "tolerances.h"

namespace pd {

namespace {

int extreme_index(const Points& x, const std::vector<int>& among, const Vec3& u, bool top) {
  if (static_cast<Eigen::Index>(among.size()) == x.cols()) {  // all of x: vectorised
    const Eigen::RowVectorXd s = u.transpose() * x;
    Eigen::Index k = 0;
    if (top)
      s.maxCoeff(&k);
    else
      s.minCoeff(&k);
    return static_cast<int>(k);
  }
  int best = among.front();
  double bv = u.dot(x.col(best));
  for (int i : among) {
    const double s = u.dot(x.col(i));
    if (top ? s > bv : s < bv) best = i, bv = s;
  }
  return best;
}

// The lowest facet in the cap from the facet normals' candidates, without a hull.
// A facet of P' − Q' is a face of P' minus a face of Q' spanning a plane: a
// facet of P' (a plane through three of its points), a facet of Q', or an edge
// of each (the cross product of a pair of P' points' difference and of Q'
// points'). So these candidates hold every facet normal. A candidate is kept
// when it is one: its P' points lie at the top of P'·n and its Q' points at the
// bottom of Q'·n (to rounding); its offset is the local support there, exactly.
// Returns false when no candidate spans a plane (collinear sets: the hull path
// decides).
bool lowest_from_candidates(const Points& p, const Points& q, const std::vector<int>& pi,
                            const std::vector<int>& qj, const Vec3& v, double cos_r,
                            std::optional<FacetCandidate>& lowest) {
  bool spanned = false;
  auto consider = [&](Vec3 n, double scale, std::initializer_list<int> on_p,
                      std::initializer_list<int> on_q) {
    const double len = n.norm();
    if (!(len > 1e-12 * scale)) return;  // parallel or coincident: no plane
    spanned = true;
    n /= len;
    if (n.dot(v) < 0) n = -n;
    if (n.dot(v) < cos_r) return;
    double hi = -std::numeric_limits<double>::infinity(), lo = -hi;
    for (int i : pi) hi = std::max(hi, p.col(i).dot(n));
    for (int j : qj) lo = std::min(lo, q.col(j).dot(n));
    const double slack = 1e-12 * std::max({1.0, std::abs(hi), std::abs(lo)});
    for (int i : on_p)
      if (p.col(i).dot(n) < hi - slack) return;  // not on P''s face at n: no facet
    for (int j : on_q)
      if (q.col(j).dot(n) > lo + slack) return;
    if (!lowest || hi - lo < lowest->offset) lowest = FacetCandidate{n, hi - lo};
  };
  auto triples = [&](const Points& x, const std::vector<int>& ids, bool of_p) {
    for (size_t a = 0; a < ids.size(); ++a)
      for (size_t b = a + 1; b < ids.size(); ++b)
        for (size_t c = b + 1; c < ids.size(); ++c) {
          const Vec3 e1 = x.col(ids[b]) - x.col(ids[a]), e2 = x.col(ids[c]) - x.col(ids[a]);
          if (of_p)
            consider(e1.cross(e2), e1.norm() * e2.norm(), {ids[a], ids[b], ids[c]}, {});
          else
            consider(e1.cross(e2), e1.norm() * e2.norm(), {}, {ids[a], ids[b], ids[c]});
        }
  };
  triples(p, pi, true);
  triples(q, qj, false);
  for (size_t a = 0; a < pi.size(); ++a)
    for (size_t b = a + 1; b < pi.size(); ++b) {
      const Vec3 e1 = p.col(pi[b]) - p.col(pi[a]);
      for (size_t c = 0; c < qj.size(); ++c)
        for (size_t d = c + 1; d < qj.size(); ++d) {
          const Vec3 e2 = q.col(qj[d]) - q.col(qj[c]);
          consider(e1.cross(e2), e1.norm() * e2.norm(), {pi[a], pi[b]}, {qj[c], qj[d]});
        }
    }
  return spanned;
}

// Candidates of lowest_from_candidates times their valuation's cost.
double candidate_work(size_t a, size_t b) {
  auto c2 = [](double n) { return n * (n - 1) / 2; };
  auto c3 = [](double n) { return n * (n - 1) * (n - 2) / 6; };
  return (c3(double(a)) + c3(double(b)) + c2(double(a)) * c2(double(b))) * double(a + b);
}

}  // namespace

std::vector<int> extreme_in_cap_among(const Points& x, const std::vector<int>& among, const Vec3& v,
                                      double radius, bool top) {
  if (among.empty()) return {};
  // If x_i is extreme at some u in the cap, then (x_i − x_k)·u >= 0 (top) for
  // every reference x_k, which needs angle(x_i − x_k, v) <= π/2 + radius:
  // (x_i − x_k)·v >= −|x_i − x_k|·sin(radius).
  const Vec3 helper = std::abs(v.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 e1 = v.cross(helper).normalized(), e2 = v.cross(e1);
  std::vector<int> refs{extreme_index(x, among, v, top)};
  for (int k = 0; k < 8; ++k) {
    const double a = k * M_PI / 4;
    const Vec3 u = std::cos(radius) * v + std::sin(radius) * (std::cos(a) * e1 + std::sin(a) * e2);
    refs.push_back(extreme_index(x, among, u, top));
  }
  const double sr = std::sin(radius), sign = top ? 1.0 : -1.0;
  std::vector<int> keep;
  for (int i : among) {
    bool ok = true;
    for (int k : refs) {
      const Vec3 d = sign * (x.col(i) - x.col(k));
      if (d.dot(v) < -d.norm() * sr * (1 + 1e-12) - 1e-15) {
        ok = false;
        break;
      }
    }
    if (ok) keep.push_back(i);
  }
  return keep;
}

std::vector<int> extreme_in_cap(const Points& x, const Vec3& v, double radius, bool top) {
  std::vector<int> all(static_cast<size_t>(x.cols()));
  for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  return extreme_in_cap_among(x, all, v, radius, top);
}

CapSearch lowest_facet_in_cap(const Points& p, const Points& q, const Vec3& v, double radius,
                              long max_points) {
  const std::vector<int> pi = extreme_in_cap(p, v, radius, true);
  const std::vector<int> qj = extreme_in_cap(q, v, radius, false);
  if (long(pi.size()) * long(qj.size()) > max_points) return {false, std::nullopt};
  return {true, lowest_local_facet(p, q, pi, qj, v, radius)};
}

std::optional<FacetCandidate> lowest_local_facet(const Points& p, const Points& q,
                                                 const std::vector<int>& pi,
                                                 const std::vector<int>& qj, const Vec3& v,
                                                 double radius) {
  const double cos_r = std::cos(radius);
  if (candidate_work(pi.size(), qj.size()) <= tol::kCandidateFacetWork) {
    std::optional<FacetCandidate> lowest;
    if (lowest_from_candidates(p, q, pi, qj, v, cos_r, lowest)) return lowest;
  }
  Points m(3, pi.size() * qj.size());
  Eigen::Index k = 0;
  for (int i : pi)
    for (int j : qj) m.col(k++) = p.col(i) - q.col(j);
  HullFacets f;
  if (m.cols() < 3) return std::nullopt;  // a vertex or an edge: no facet normal inside
  if (m.cols() == 3 || !hull_facets(m, f)) {
    // Flat: the polygon itself is the one facet, its normal taken towards v.
    const Vec3 c = m.rowwise().mean();
    const Points d = m.colwise() - c;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(d * d.transpose());
    Vec3 n = eig.eigenvectors().col(0);
    if (n.dot(v) < 0) n = -n;
    if (n.dot(v) < cos_r) return std::nullopt;
    return FacetCandidate{n, (n.transpose() * m).maxCoeff()};
  }
  std::optional<FacetCandidate> lowest;
  for (size_t t = 0; t < f.normals.size(); ++t) {
    if (f.normals[t].dot(v) < cos_r) continue;
    const double offset = -f.offsets[t];
    if (!lowest || offset < lowest->offset) lowest = FacetCandidate{f.normals[t], offset};
  }
  return lowest;
}

}  // namespace pd
