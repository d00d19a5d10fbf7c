#include "solve/signed_distance.h"

#include "solve/exact.h"
#include "solve/local_search.h"
#include "solve/methods.h"
#include "solve/mlsl.h"
#include "solve/objective.h"

namespace pd {

namespace {

// Separated: the gap has one minimum on the sphere (−distance), so the
// α-free local solve `lr` from any direction v0 with a negative gap reaches it.
SignedSolution separation(const PairProblem& pr, const LocalResult& lr, const Vec3& v0,
                          SolveStats stats) {
  SignedSolution out;
  const double g0 = pr.gap(v0);
  const bool use = lr.converged && lr.gap <= g0;
  out.value = pr.frame().length_to_world(use ? lr.gap : g0);
  out.direction = use ? lr.v : v0;
  if (!lr.converged) out.fallback = "distance solve did not converge (" + lr.status + ")";
  stats.alpha_evaluations += pr.evaluations();
  out.stats = stats;
  return out;
}

}  // namespace

SignedSolution signed_distance(const Points& a, const Points& b, const SolverSettings& s,
                               IpoptLocalSolver& ipopt, const std::optional<Vec3>& warm) {
  const PairProblem pr(a, b);
  if (s.method == Method::kExact) {
    const DepthSolution e = exact_depth(pr.p(), pr.q());
    SignedSolution out;
    const double dist = e.distance.value_or(0.0);
    out.value = pr.frame().length_to_world(e.depth > 0 ? e.depth : (dist > 0 ? -dist : 0.0));
    out.direction = e.direction;  // both conventions point from a to b
    return out;
  }
  SolveStats warm_stats;  // a warm start that did not settle the pair still did its work
  if (warm) {
    SolveStats& stats = warm_stats;
    const LocalResult lr = polish(pr, ipopt, *warm, stats, true);
    Vec3 v = lr.v;
    double g = lr.gap;
    if (const double g0 = pr.gap(*warm); g0 < g) v = *warm, g = g0;
    // Still apart: that α-free solve was the distance solve.
    if (g < 0) return separation(pr, lr, *warm, stats);
    // Overlapping: a local optimum from the warm start, proved global (or not).
    if (certify_minimum(pr, v, g, stats)) {
      SignedSolution out;
      out.value = pr.frame().length_to_world(std::max(0.0, g));
      out.direction = v;
      stats.alpha_evaluations += pr.evaluations();
      out.stats = stats;
      return out;
    }
  }
  // From scratch, on a problem of its own (one more centring of the points:
  // O(n + m), small beside the solve).
  DepthSolution d = solve_convex_pair(a, b, s, ipopt);
  d.stats += warm_stats;
  if (d.depth > 0) {
    d.stats.alpha_evaluations += pr.evaluations();  // the warm start's gap evaluations
    return {d.depth, d.direction, d.stats, d.fallback};
  }
  // depth 0: d.direction separates (gap <= 0 there); the distance from it
  // (separation() counts pr's evaluations, the warm start's included).
  SolveStats stats = d.stats;
  const LocalResult lr = polish(pr, ipopt, d.direction, stats, true);
  return separation(pr, lr, d.direction, stats);
}

}  // namespace pd
