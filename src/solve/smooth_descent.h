// A cheap descent on the gap before Ipopt: Riemannian Newton steps on the unit
// sphere for the log-sum-exp smoothing
//   f_μ(v) = μ·log Σ_i exp(p_i·v/μ) + μ·log Σ_j exp(−q_j·v/μ)  (>= gap(v), within μ·log(nm)),
// with μ decreasing. Each step is O(n + m). It brings a sample next to the
// nearest local optimum so that Ipopt starts there and needs few iterations.
#pragma once

#include "geometry/types.h"

namespace pd {

struct DescentOutcome {
  Vec3 v;
  long evaluations = 0;   ///< smoothed objective evaluations, O(n + m) each
  double smoothed = 0.0;  ///< f_μ(v) at the end, for the final μ
  double mu = 0.0;        ///< the final μ
};

DescentOutcome smooth_descent(const Points& p, const Points& q, const Vec3& start);

}  // namespace pd
