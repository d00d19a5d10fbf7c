// Grid methods of the paper: GS-k (Agarwal et al.'s grid over (θ, φ), no local
// solve) and GS-SQP (a k×k grid of starts, each an Ipopt local search).
#pragma once

#include "solve/ipopt_local.h"
#include "solve/objective.h"
#include "solve/result.h"

namespace pd {

/// GS-k: θ = aπ/k (a = 0..2k−1), φ = −π/2 + bπ/k (b = 0..k): 2k(k+1) directions,
/// as counted in the paper's Table II (k = 180 is one degree in each angle).
DepthSolution grid_depth(const PairProblem& pr, int k);

/// GS-SQP: starts at the centres of a k×k grid of cells of the (θ, φ) box.
DepthSolution gs_local_depth(const PairProblem& pr, IpoptLocalSolver& ipopt, int k);

}  // namespace pd
