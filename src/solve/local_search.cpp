#include "solve/local_search.h"

#include <algorithm>

#include "solve/facet_snap.h"
#include "solve/smooth_descent.h"
#include "tolerances.h"

namespace pd {

namespace {

void count(const LocalOutcome& o, SolveStats& stats) {
  ++stats.ipopt_calls;
  stats.ipopt_iterations += o.iterations;
  if (!o.converged) ++stats.ipopt_failures;
}

// Adds the vertices that the reduced solution violates; returns how many.
size_t add_violators(const Points& x, const Vec3& v, double level, bool top,
                     std::vector<int>& ids) {
  const Eigen::RowVectorXd s = v.transpose() * x;
  std::vector<char> in(s.size(), 0);
  for (int k : ids) in[k] = 1;
  size_t added = 0;
  const double slack = tol::kPolishSlack;
  for (Eigen::Index k = 0; k < s.size(); ++k) {
    if (in[k]) continue;
    if (top ? s[k] > level + slack : s[k] < level - slack) {
      ids.push_back(static_cast<int>(k));
      ++added;
    }
  }
  std::sort(ids.begin(), ids.end());
  return added;
}

}  // namespace

LocalResult paper_local_search(const PairProblem& pr, IpoptLocalSolver& ipopt, const Vec3& v0,
                               SolveStats& stats) {
  const auto pi = all_indices(pr.p().cols()), qj = all_indices(pr.q().cols());
  const LocalOutcome o =
      ipopt.solve(pr.p(), pr.q(), pi, qj, IpoptLocalSolver::paper_start(pr.p(), pr.q(), v0), false);
  count(o, stats);
  ++stats.local_solves;
  return {o.v, pr.gap(o.v), o.converged, o.converged ? "" : o.status};
}

DescentOutcome descend(const PairProblem& pr, const Vec3& v0, SolveStats& stats) {
  ++stats.local_solves;
  const DescentOutcome d = smooth_descent(pr.p(), pr.q(), v0);
  stats.alpha_evaluations += d.evaluations;
  return d;
}

LocalResult polish(const PairProblem& pr, IpoptLocalSolver& ipopt, const Vec3& v0,
                   SolveStats& stats, bool alpha_free) {
  // The reduced problem: a band in the unit frame that holds every vertex that
  // is active within a few degrees of the descent's end point.
  const double band = tol::kPolishBand;
  std::vector<int> pi = near_extreme(pr.p(), v0, band, true);
  std::vector<int> qj = near_extreme(pr.q(), v0, band, false);
  LocalStart start = IpoptLocalSolver::paper_start(pr.p(), pr.q(), v0);
  LocalOutcome o;
  for (int round = 0; round < 6; ++round) {
    o = ipopt.solve(pr.p(), pr.q(), pi, qj, start, true, alpha_free);
    count(o, stats);
    if (!o.converged) break;
    // Feasibility over all vertices: the reduced optimum is the full one when no
    // vertex outside the subsets lies beyond its planes.
    const size_t added = add_violators(pr.p(), o.v, o.c, true, pi) +
                         add_violators(pr.q(), o.v, o.c - o.alpha, false, qj);
    if (added == 0) break;
    start = IpoptLocalSolver::paper_start(pr.p(), pr.q(), o.v);
  }
  if (!o.converged) {
    // Retry once on the full problem from the paper's cold start.
    const auto all_p = all_indices(pr.p().cols()), all_q = all_indices(pr.q().cols());
    o = ipopt.solve(pr.p(), pr.q(), all_p, all_q, IpoptLocalSolver::paper_start(pr.p(), pr.q(), v0),
                    false, alpha_free);
    count(o, stats);
    if (!o.converged) return {o.v, pr.gap(o.v), false, o.status};
  }
  LocalResult r{o.v, pr.gap(o.v), true, ""};
  if (const auto n = snap_to_facet(pr.p(), pr.q(), o.v)) {
    const double g = pr.gap(*n);
    // Both values bound the minimum from above; the snap must also stay at this
    // optimum (a wrong active set could jump elsewhere).
    if (g <= r.gap && angle_between(*n, o.v) < tol::kPolishSnapAngle) r = {*n, g, true, ""};
  }
  return r;
}

}  // namespace pd
