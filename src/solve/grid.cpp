#include "solve/grid.h"

#include <limits>

#include "solve/local_search.h"

namespace pd {

DepthSolution grid_depth(const PairProblem& pr, int k) {
  DepthSolution s;
  double best = std::numeric_limits<double>::infinity();
  for (int b = 0; b <= k; ++b) {
    for (int a = 0; a < 2 * k; ++a) {
      const Vec3 v = direction_from_angles(a * M_PI / k, -M_PI / 2 + b * M_PI / k);
      const double g = pr.gap(v);
      if (g < best) best = g, s.direction = v;
    }
  }
  s.depth = std::max(0.0, best);
  s.stats.alpha_evaluations = pr.evaluations();
  return s;
}

DepthSolution gs_local_depth(const PairProblem& pr, IpoptLocalSolver& ipopt, int k) {
  DepthSolution s;
  double best = std::numeric_limits<double>::infinity();
  bool any = false;
  std::string last_failure;
  for (int b = 0; b < k; ++b) {
    for (int a = 0; a < k; ++a) {
      const Vec3 v0 =
          direction_from_angles((a + 0.5) * 2 * M_PI / k, -M_PI / 2 + (b + 0.5) * M_PI / k);
      const LocalResult r = paper_local_search(pr, ipopt, v0, s.stats);
      if (r.converged)
        any = true;
      else
        last_failure = r.status;
      if (r.gap < best) best = r.gap, s.direction = r.v;
    }
  }
  s.depth = std::max(0.0, best);
  s.stats.alpha_evaluations += pr.evaluations();
  if (!any) s.fallback = "no local solve converged (" + last_failure + ")";
  return s;
}

}  // namespace pd
