// One entry point for every depth method: a convex pair in world coordinates in,
// a depth in world units out.
#pragma once

#include "solve/ipopt_local.h"
#include "solve/result.h"
#include "solve/settings.h"

namespace pd {

/// Solves one pair of convex point sets (a, b in world coordinates). Methods
/// that cannot certify their answer fall back to `exact` and say so in
/// `fallback`. Throws std::runtime_error only if even that fails.
DepthSolution solve_convex_pair(const Points& a, const Points& b, const SolverSettings& s,
                                IpoptLocalSolver& ipopt);

}  // namespace pd
