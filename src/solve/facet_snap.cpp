#include "solve/facet_snap.h"

#include <Eigen/SVD>
#include <vector>

#include "solve/objective.h"
#include "tolerances.h"

namespace pd {

namespace {

// Tries the active-set tolerances in `bands` from loose to tight (see the header).
std::optional<Vec3> snap_with(const Points& p, const Points& q, const Vec3& v,
                              const std::vector<double>& bands) {
  for (double t : bands) {
    const std::vector<int> a = near_extreme(p, v, t, true), b = near_extreme(q, v, t, false);
    if (a.size() + b.size() < 3) return std::nullopt;  // a vertex or an edge: no facet
    Eigen::MatrixXd edges(a.size() + b.size() - 2, 3);
    Eigen::Index r = 0;
    for (size_t k = 1; k < a.size(); ++k) edges.row(r++) = (p.col(a[k]) - p.col(a[0])).transpose();
    for (size_t k = 1; k < b.size(); ++k) edges.row(r++) = (q.col(b[k]) - q.col(b[0])).transpose();
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(edges, Eigen::ComputeFullV);
    const Eigen::VectorXd s = svd.singularValues();
    if (s.size() < 2 || s[1] <= tol::kSnapResidual) return std::nullopt;  // rank < 2
    if (s.size() == 3 && s[2] > tol::kSnapResidual) continue;  // too many active: tighten
    Vec3 n = svd.matrixV().col(2);
    if (n.dot(v) < 0) n = -n;
    return n.normalized();
  }
  return std::nullopt;
}

}  // namespace

std::optional<Vec3> snap_to_facet(const Points& p, const Points& q, const Vec3& v) {
  return snap_with(p, q, v, {tol::kActiveLoose, 1e-8, 1e-9, tol::kActiveTight});
}

std::optional<Vec3> snap_from_descent(const Points& p, const Points& q, const Vec3& v) {
  std::vector<double> bands;
  for (double t = tol::kDescentSnapBand; t > tol::kActiveLoose * 1.5; t *= 0.1) bands.push_back(t);
  for (double t : {tol::kActiveLoose, 1e-8, 1e-9, tol::kActiveTight}) bands.push_back(t);
  return snap_with(p, q, v, bands);
}

}  // namespace pd
