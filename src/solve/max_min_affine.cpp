#include "solve/max_min_affine.h"

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <vector>

namespace pd {

namespace {

// max over the box of Σ λ_k f_k: its value at the centre plus, per axis, the
// half-width times the absolute combined slope.
double dual_value(const std::vector<Affine>& f, const Eigen::VectorXd& lambda, const Vec3& lo,
                  const Vec3& hi) {
  const Vec3 centre = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  double value = 0.0;
  Vec3 slope = Vec3::Zero();
  for (size_t k = 0; k < f.size(); ++k) {
    value += lambda[k] * (f[k].value + f[k].slope.dot(centre));
    slope += lambda[k] * f[k].slope;
  }
  return value + half.dot(slope.cwiseAbs());
}

}  // namespace

double min_max_affine(const std::vector<Affine>& f, const Vec3& lo, const Vec3& hi) {
  const Vec3 centre = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  double least = std::numeric_limits<double>::infinity();
  for (const Affine& a : f)
    least = std::min(least, a.value + a.slope.dot(centre) + half.dot(a.slope.cwiseAbs()));
  return least;
}

double max_min_affine(const std::vector<Affine>& f, const Vec3& lo, const Vec3& hi) {
  const int m = static_cast<int>(f.size());
  if (m == 0) return std::numeric_limits<double>::infinity();
  if (m == 1) return dual_value(f, Eigen::VectorXd::Ones(1), lo, hi);
  // Primal: x = lo + y, 0 ≤ y ≤ hi − lo, t = τ − M, maximise τ ≥ 0 subject to
  // τ − g_k·y ≤ f_k(lo) + M. M makes every right-hand side ≥ 0, so y = 0, τ = 0
  // is a feasible basis and one phase of the simplex suffices.
  const Vec3 w = hi - lo;
  double shift = 0.0;
  for (const Affine& a : f) shift = std::max(shift, -(a.value + a.slope.dot(lo)));
  const int rows = m + 3, vars = 4, cols = vars + rows + 1;  // + slacks + rhs
  // Row-major and flat: each pivot is row operations over contiguous memory
  // (this solve runs once per cell and model choice, the thickness's inner loop).
  std::vector<double> T(static_cast<size_t>(rows + 1) * cols, 0.0);
  const auto at = [&](int i, int j) -> double& { return T[static_cast<size_t>(i) * cols + j]; };
  std::vector<int> basis(rows), nonzero;
  nonzero.reserve(static_cast<size_t>(cols));
  for (int k = 0; k < m; ++k) {
    for (int d = 0; d < 3; ++d) at(k, d) = -f[k].slope[d];
    at(k, 3) = 1.0;
    at(k, vars + k) = 1.0;
    at(k, cols - 1) = f[k].value + f[k].slope.dot(lo) + shift;
    basis[k] = vars + k;
  }
  for (int d = 0; d < 3; ++d) {
    at(m + d, d) = 1.0;
    at(m + d, vars + m + d) = 1.0;
    at(m + d, cols - 1) = w[d];
    basis[m + d] = vars + m + d;
  }
  at(rows, 3) = -1.0;  // objective row: maximise τ
  for (int iter = 0; iter < 50 * (rows + vars); ++iter) {
    int enter = -1;  // Bland's rule: the first improving column, so no cycling
    for (int j = 0; j < cols - 1 && enter < 0; ++j)
      if (at(rows, j) < -1e-12) enter = j;
    if (enter < 0) break;
    int leave = -1;
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < rows; ++i)
      if (at(i, enter) > 1e-12) {
        const double ratio = at(i, cols - 1) / at(i, enter);
        if (ratio < best || (ratio == best && basis[i] < basis[leave])) best = ratio, leave = i;
      }
    if (leave < 0) break;  // unbounded: cannot happen (the box bounds y, each row τ)
    double* pivot = &at(leave, 0);
    const double p = pivot[enter];
    // The pivot row is mostly zeros (slack columns): the other rows change in
    // its nonzero columns only, the same arithmetic on far fewer entries.
    nonzero.clear();
    for (int j = 0; j < cols; ++j) {
      pivot[j] /= p;
      if (pivot[j] != 0.0) nonzero.push_back(j);
    }
    for (int i = 0; i <= rows; ++i) {
      double* row = &at(i, 0);
      const double factor = row[enter];
      if (i == leave || factor == 0.0) continue;
      for (const int j : nonzero) row[j] -= factor * pivot[j];
    }
    basis[leave] = enter;
  }
  // The duals of the m rows are the objective row's entries under their slacks.
  Eigen::VectorXd lambda(m);
  for (int k = 0; k < m; ++k) lambda[k] = std::max(0.0, at(rows, vars + k));
  const double sum = lambda.sum();
  if (!(sum > 0) || !std::isfinite(sum))
    lambda.setConstant(1.0 / m);
  else
    lambda /= sum;
  return dual_value(f, lambda, lo, hi);
}

}  // namespace pd
