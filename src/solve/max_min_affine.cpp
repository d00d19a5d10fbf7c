#include "solve/max_min_affine.h"

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <array>
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
  // The dual, solved by the revised simplex: with y = x − lo in [0, w] and
  // a_k = f_k(lo), minimise Σ λ_k a_k + Σ ν_d w_d over λ, ν, s ≥ 0 with
  // Σ λ_k = 1 and ν_d − Σ λ_k g_kd − s_d = 0 (d = 1, 2, 3): four rows, so a
  // basis is 4 × 4 and an iteration costs O(m), where the primal tableau of
  // m + 3 rows cost O(m²). Columns: λ_0 … λ_{m−1}, ν_0 … ν_2, s_0 … s_2.
  const Vec3 w = hi - lo;
  const int n = m + 6;
  const auto column = [&](int j) -> Eigen::Vector4d {
    if (j < m) return {1.0, -f[j].slope.x(), -f[j].slope.y(), -f[j].slope.z()};
    Eigen::Vector4d c = Eigen::Vector4d::Zero();
    c[1 + (j - m) % 3] = j < m + 3 ? 1.0 : -1.0;
    return c;
  };
  // The costs' buffer is kept per thread: the solve runs some hundred
  // thousand times in a scene's searches, and is not to allocate each time.
  thread_local std::vector<double> cost;
  cost.assign(static_cast<size_t>(n), 0.0);
  double scale = 1.0;
  for (int k = 0; k < m; ++k) {
    cost[k] = f[k].value + f[k].slope.dot(lo);
    scale = std::max({scale, std::abs(cost[k]), f[k].slope.cwiseAbs().maxCoeff()});
  }
  for (int d = 0; d < 3; ++d) cost[m + d] = w[d], scale = std::max(scale, std::abs(w[d]));
  const double eps = 1e-12 * scale;
  // A feasible start without a first phase: all weight on the function with
  // the least maximum over the box (min_max_affine's choice), each ν_d or s_d
  // taking up its slope's part.
  int start = 0;
  double least = std::numeric_limits<double>::infinity();
  const Vec3 centre = 0.5 * (lo + hi), half = 0.5 * w;
  for (int k = 0; k < m; ++k) {
    const double top = f[k].value + f[k].slope.dot(centre) + half.dot(f[k].slope.cwiseAbs());
    if (top < least) least = top, start = k;
  }
  std::array<int, 4> basis{start, 0, 0, 0};
  for (int d = 0; d < 3; ++d) basis[1 + d] = f[start].slope[d] >= 0 ? m + d : m + 3 + d;
  const Eigen::Vector4d b(1.0, 0.0, 0.0, 0.0);
  Eigen::Matrix4d B;
  Eigen::Vector4d x = Eigen::Vector4d::Zero();
  for (int iter = 0; iter < 50 * n; ++iter) {
    for (int i = 0; i < 4; ++i) B.col(i) = column(basis[i]);
    // A 4 × 4 basis is inverted in closed form (Eigen's cofactors), three
    // times cheaper than a pivoted factorisation here; its rounding only
    // moves the weights λ, and the bound is the dual value of whatever
    // weights come out (dual_value), sound for any.
    const Eigen::Matrix4d inverse = B.inverse();
    x = inverse * b;
    Eigen::Vector4d c_b;
    for (int i = 0; i < 4; ++i) c_b[i] = cost[basis[i]];
    const Eigen::Vector4d pi = inverse.transpose() * c_b;
    const auto in_basis = [&](int j) {
      return j == basis[0] || j == basis[1] || j == basis[2] || j == basis[3];
    };
    int enter = -1;  // Bland's rule: the first improving column, so no cycling
    for (int j = 0; j < n && enter < 0; ++j)
      if (!in_basis(j) && cost[j] - pi.dot(column(j)) < -eps) enter = j;
    if (enter < 0) break;  // optimal
    const Eigen::Vector4d dir = inverse * column(enter);
    int leave = -1;
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 4; ++i)
      if (dir[i] > eps) {
        const double ratio = std::max(0.0, x[i]) / dir[i];
        if (ratio < best || (ratio == best && leave >= 0 && basis[i] < basis[leave]))
          best = ratio, leave = i;
      }
    if (leave < 0) break;  // unbounded: cannot happen (the objective is bounded below)
    basis[leave] = enter;
  }
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m);
  for (int i = 0; i < 4; ++i)
    if (basis[i] < m) lambda[basis[i]] = std::max(0.0, x[i]);
  const double sum = lambda.sum();
  if (!(sum > 0) || !std::isfinite(sum))
    lambda.setConstant(1.0 / m);
  else
    lambda /= sum;
  return dual_value(f, lambda, lo, hi);
}

}  // namespace pd
