#include "solve/facet_snap.h"

#include <Eigen/SVD>
#include <iterator>
#include <vector>

#include "solve/neighbourhood.h"
#include "solve/objective.h"
#include "tolerances.h"

namespace pd {

namespace {

// The vertices within `band` of the extreme support value `e` (the largest of
// s when top, else the smallest).
std::vector<int> within(const Eigen::RowVectorXd& s, double e, double band, bool top) {
  std::vector<int> ids;
  for (Eigen::Index k = 0; k < s.size(); ++k)
    if (top ? s[k] >= e - band : s[k] <= e + band) ids.push_back(static_cast<int>(k));
  return ids;
}

// The fitted plane is only within kSnapResidual of the active vertices (their
// faces are flat to rounding of the input, a float32 mesh's to ~1e-7), so its
// gap is off by up to that much: too much for a contact, which mlsl settles at
// kTouch. The facet itself is exact: the lowest facet of P − Q with its normal
// in a small cap around the fit, from the vertices extreme there. None there,
// or too many vertices for one exact local search (bumpy faces of a thousand
// vertices): the fit, a candidate the certificate checks.
Vec3 exact_facet(const Points& p, const Points& q, const Vec3& fit) {
  const std::vector<int> pi = extreme_in_cap(p, fit, tol::kSnapCap, true);
  const std::vector<int> qj = extreme_in_cap(q, fit, tol::kSnapCap, false);
  if (long(pi.size()) * long(qj.size()) > tol::kNeighbourhoodPoints) return fit;
  if (const auto f = lowest_local_facet(p, q, pi, qj, fit, tol::kSnapCap)) return f->normal;
  return fit;
}

// Tries the active-set tolerances in `bands` from loose to tight (see the header).
// The support values are computed once; a band whose active sets equal the
// previous band's repeats its verdict (too many active: tighten) and is skipped.
std::optional<Vec3> snap_with(const Points& p, const Points& q, const Vec3& v,
                              const std::vector<double>& bands) {
  const Eigen::RowVectorXd sp = v.transpose() * p, sq = v.transpose() * q;
  const double ep = sp.maxCoeff(), eq = sq.minCoeff();
  std::vector<int> last_a, last_b;
  for (double t : bands) {
    std::vector<int> a = within(sp, ep, t, true), b = within(sq, eq, t, false);
    if (a.size() + b.size() < 3) return std::nullopt;  // a vertex or an edge: no facet
    if (a == last_a && b == last_b) continue;
    // Rows are edges between active vertices: 3 columns at compile time keep
    // the SVD's 3 × 3 stage on the stack.
    Eigen::Matrix<double, Eigen::Dynamic, 3> edges(a.size() + b.size() - 2, 3);
    Eigen::Index r = 0;
    for (size_t k = 1; k < a.size(); ++k) edges.row(r++) = (p.col(a[k]) - p.col(a[0])).transpose();
    for (size_t k = 1; k < b.size(); ++k) edges.row(r++) = (q.col(b[k]) - q.col(b[0])).transpose();
    Eigen::JacobiSVD<Eigen::Matrix<double, Eigen::Dynamic, 3>> svd(edges, Eigen::ComputeFullV);
    const Eigen::VectorXd s = svd.singularValues();
    if (s.size() < 2 || s[1] <= tol::kSnapResidual) return std::nullopt;  // rank < 2
    if (s.size() == 3 && s[2] > tol::kSnapResidual) {  // too many active: tighten
      last_a = std::move(a);
      last_b = std::move(b);
      continue;
    }
    Vec3 n = svd.matrixV().col(2);
    if (n.dot(v) < 0) n = -n;
    return exact_facet(p, q, n.normalized());
  }
  return std::nullopt;
}

}  // namespace

std::optional<Vec3> snap_to_facet(const Points& p, const Points& q, const Vec3& v) {
  return snap_with(p, q, v, {std::begin(tol::kSnapBands), std::end(tol::kSnapBands)});
}

std::optional<Vec3> snap_from_descent(const Points& p, const Points& q, const Vec3& v) {
  std::vector<double> bands;
  for (double t = tol::kDescentSnapBand; t > tol::kActiveLoose * 1.5; t *= 0.1) bands.push_back(t);
  bands.insert(bands.end(), std::begin(tol::kSnapBands), std::end(tol::kSnapBands));
  return snap_with(p, q, v, bands);
}

}  // namespace pd
