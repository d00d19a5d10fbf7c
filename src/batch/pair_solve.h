// Solving one pair of parts: every piece pair, the deepest one counts.
#pragma once

#include "batch/pair_result.h"
#include "scene/parts.h"
#include "solve/ipopt_local.h"
#include "solve/settings.h"

namespace pd {

PairResult solve_part_pair(int ia, const Part& a, int ib, const Part& b, const SolverSettings& s,
                           double tolerance, IpoptLocalSolver& ipopt);

}  // namespace pd
