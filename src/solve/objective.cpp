#include "solve/objective.h"

#include <algorithm>
#include <vector>

namespace pd {

PairProblem::PairProblem(const Points& a_world, const Points& b_world)
    : frame_(pair_frame(a_world, b_world)),
      p_(frame_.to_local(a_world)),
      q_(frame_.to_local(b_world)),
      p_soa_(p_),
      q_soa_(q_) {}

double PairProblem::gap(const Vec3& v) const {
  ++evaluations_;
  return p_soa_.max_dot(v) - q_soa_.min_dot(v);
}

double PairProblem::support(const Vec3& v, Vec3& point) const {
  ++evaluations_;
  Eigen::Index i = 0, j = 0;
  const double g = p_soa_.max_dot(v, &i) - q_soa_.min_dot(v, &j);
  point = p_.col(i) - q_.col(j);
  return g;
}

double PairProblem::support(const Vec3& v, Vec3& point, MinkowskiIndex& id) const {
  ++evaluations_;
  Eigen::Index i = 0, j = 0;
  const double g = p_soa_.max_dot(v, &i) - q_soa_.min_dot(v, &j);
  point = p_.col(i) - q_.col(j);
  id = {static_cast<int>(i), static_cast<int>(j)};
  return g;
}

void PairProblem::gaps(const Vec3* v, size_t count, double* out) const {
  evaluations_ += static_cast<long>(count);
  thread_local std::vector<double> low;  // max_i −q_i·v = −min_j q_j·v
  low.resize(count);
  p_soa_.max_dots(v, count, 1.0, out);
  q_soa_.max_dots(v, count, -1.0, low.data());
  for (size_t k = 0; k < count; ++k) out[k] -= -low[k];  // gap()'s subtraction, exactly
}

std::vector<int> near_extreme(const Points& x, const Vec3& v, double band, bool top) {
  const Eigen::RowVectorXd s = v.transpose() * x;
  const double e = top ? s.maxCoeff() : s.minCoeff();
  std::vector<int> ids;
  for (Eigen::Index k = 0; k < s.size(); ++k)
    if (top ? s[k] >= e - band : s[k] <= e + band) ids.push_back(static_cast<int>(k));
  return ids;
}

void angles_from_direction(const Vec3& v, double& theta, double& phi) {
  const double rho = std::hypot(v.x(), v.y());
  phi = std::atan2(v.z(), rho);
  if (rho == 0.0) {
    theta = M_PI / 2;  // the pole: θ is arbitrary, so always the same value
    return;
  }
  theta = std::atan2(v.y(), v.x());
  if (theta < 0) theta += 2 * M_PI;
  if (theta >= 2 * M_PI) theta = 0.0;  // wrap-around of −0 rounding
}

double angle_between(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

}  // namespace pd
