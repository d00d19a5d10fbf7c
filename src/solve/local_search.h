// One local search of MLSL: from a direction to a local optimum of the gap.
#pragma once

#include "solve/ipopt_local.h"
#include "solve/objective.h"
#include "solve/result.h"
#include "solve/smooth_descent.h"

namespace pd {

struct LocalResult {
  Vec3 v = Vec3::UnitZ();
  double gap = 0.0;  ///< gap(v) over every vertex: always a true upper bound on the minimum
  bool converged = false;
  std::string status;  ///< Ipopt's status when it did not converge
};

/// The paper's Algorithm 2: Ipopt on the full 5-variable problem from the start
/// (v0, c0, α0); the result mapped back (here: kept as the unit vector).
LocalResult paper_local_search(const PairProblem& pr, IpoptLocalSolver& ipopt, const Vec3& v0,
                               SolveStats& stats);

/// pdcheck's local search in two steps. descend(): the smooth descent to the
/// bottom of the basin, O(n + m) per step, no Ipopt. polish(): Ipopt on the
/// vertices that can be active there (grown until no vertex outside is
/// violated), then the facet snap. Same optimum as the paper's search, far
/// fewer Ipopt iterations, depth exact to rounding.
DescentOutcome descend(const PairProblem& pr, const Vec3& v0, SolveStats& stats);
LocalResult polish(const PairProblem& pr, IpoptLocalSolver& ipopt, const Vec3& v0,
                   SolveStats& stats, bool alpha_free = false);

}  // namespace pd
