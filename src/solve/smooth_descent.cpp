#include "solve/smooth_descent.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>

#include "tolerances.h"

namespace pd {

namespace {

struct Smoothed {
  double value = 0.0;
  Vec3 grad = Vec3::Zero();
  Eigen::Matrix3d hess = Eigen::Matrix3d::Zero();
};

// μ·log Σ exp(s·x_k·v/μ) for s = ±1, with its gradient and Hessian in v. Terms
// more than 40μ below the top weigh less than 4e-18 relative: they are skipped
// in the derivatives, which then cost O(active) after the O(n) dot products.
Smoothed log_sum_exp(const Points& x, const Vec3& v, double s, double mu, bool derivatives) {
  const Eigen::RowVectorXd t = s * (v.transpose() * x);
  const double top = t.maxCoeff(), cut = top - tol::kLogSumExpCut * mu;
  double z = 0.0;
  Vec3 g = Vec3::Zero();
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  for (Eigen::Index k = 0; k < t.size(); ++k) {
    if (t[k] < cut) continue;
    const double w = std::exp((t[k] - top) / mu);
    z += w;
    if (derivatives) {
      const Vec3 xk = x.col(k);
      g += w * xk;
      h.noalias() += w * xk * xk.transpose();
    }
  }
  Smoothed r;
  r.value = top + mu * std::log(z);
  if (derivatives) {
    r.grad = s * g / z;
    r.hess = (h / z - r.grad * r.grad.transpose()) / mu;
  }
  return r;
}

Smoothed smoothed_gap(const Points& p, const Points& q, const Vec3& v, double mu, bool d) {
  Smoothed a = log_sum_exp(p, v, 1.0, mu, d), b = log_sum_exp(q, v, -1.0, mu, d);
  return {a.value + b.value, a.grad + b.grad, a.hess + b.hess};
}

// An orthonormal basis of the tangent plane at v.
Eigen::Matrix<double, 3, 2> tangent_basis(const Vec3& v) {
  const Vec3 helper = std::abs(v.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 e1 = v.cross(helper).normalized();
  Eigen::Matrix<double, 3, 2> b;
  b.col(0) = e1;
  b.col(1) = v.cross(e1);
  return b;
}

}  // namespace

DescentOutcome smooth_descent(const Points& p, const Points& q, const Vec3& start) {
  DescentOutcome out{start.normalized(), 0};
  Vec3& v = out.v;
  // The unit frame puts both parts in the unit ball, so μ is an absolute length.
  for (double mu : tol::kDescentMu) {
    for (int it = 0; it < tol::kDescentSteps; ++it) {
      const Smoothed f = smoothed_gap(p, q, v, mu, true);
      ++out.evaluations;
      out.smoothed = f.value;
      out.mu = mu;
      const auto b = tangent_basis(v);
      const Eigen::Vector2d g = b.transpose() * f.grad;
      if (g.norm() < tol::kDescentStationary * mu) break;
      // Riemannian Hessian on the sphere: projected Hessian minus (v·∇f)·I.
      Eigen::Matrix2d h = b.transpose() * f.hess * b - v.dot(f.grad) * Eigen::Matrix2d::Identity();
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(h);
      Eigen::Vector2d d;
      if (eig.eigenvalues().minCoeff() > 1e-12)
        d = -h.ldlt().solve(g);
      else
        d = -g / std::max(eig.eigenvalues().cwiseAbs().maxCoeff(), 1.0);
      if (d.norm() > 0.5) d *= 0.5 / d.norm();  // stay within a chart of the sphere
      // Backtracking (Armijo) along the retraction v ← normalise(v + B d).
      double step = 1.0;
      bool moved = false;
      for (int ls = 0; ls < tol::kDescentHalvings; ++ls, step *= 0.5) {
        const Vec3 trial = (v + b * (step * d)).normalized();
        ++out.evaluations;
        const double ft = smoothed_gap(p, q, trial, mu, false).value;
        if (ft <= f.value + tol::kDescentArmijo * step * g.dot(d)) {
          v = trial;
          out.smoothed = ft;
          moved = true;
          break;
        }
      }
      if (!moved) break;
    }
  }
  return out;
}

}  // namespace pd
