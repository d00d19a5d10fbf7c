// The exact optimum of max over a box of min_k f_k by vertex enumeration: the
// reference the LP and the overlap thickness are tested against (small problems only).
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "solve/max_min_affine.h"

namespace pd {

// The exact max over the box of min_k f_k: the LP max t s.t. t ≤ f_k(x),
// lo ≤ x ≤ hi has its optimum at a vertex where 4 of its constraints are tight.
inline double max_min_affine_reference(const std::vector<Affine>& f, const Vec3& lo,
                                       const Vec3& hi) {
  struct Row {
    Eigen::Vector4d a;  // a·(x, t) = b at the constraint's boundary
    double b;
  };
  std::vector<Row> rows;
  for (const Affine& g : f)
    rows.push_back({Eigen::Vector4d(-g.slope.x(), -g.slope.y(), -g.slope.z(), 1), g.value});
  for (int d = 0; d < 3; ++d) {
    Eigen::Vector4d e = Eigen::Vector4d::Zero();
    e[d] = 1;
    rows.push_back({e, hi[d]});
    rows.push_back({-e, -lo[d]});
  }
  const int n = static_cast<int>(rows.size());
  double best = -INFINITY;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k)
        for (int l = k + 1; l < n; ++l) {
          Eigen::Matrix4d A;
          Eigen::Vector4d b;
          int r = 0;
          for (int q : {i, j, k, l}) A.row(r) = rows[q].a.transpose(), b[r++] = rows[q].b;
          Eigen::FullPivLU<Eigen::Matrix4d> lu(A);
          if (lu.rank() < 4) continue;
          const Eigen::Vector4d z = lu.solve(b);
          bool feasible = true;
          for (const Row& row : rows) feasible = feasible && row.a.dot(z) <= row.b + 1e-9;
          if (feasible) best = std::max(best, z[3]);
        }
  return best;
}

}  // namespace pd
