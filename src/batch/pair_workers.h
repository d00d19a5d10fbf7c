// The worker pool of pair solves (the hull stage's pairs, the refinement's
// piece pairs): costliest first, one Ipopt per worker, a progress line, each
// answer decoded in the parent (results/codec.h's complete encoding).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "batch/pair_solve.h"
#include "batch/run.h"
#include "scene/parts.h"

namespace pd {

/// One pair of a pool: the parts' indices (as the result gives them) and the
/// parts to solve (the run's, or their pieces).
struct PairJob {
  int a = -1, b = -1;
  const Part* part_a = nullptr;
  const Part* part_b = nullptr;
};

/// Solves `job(k)` for every k of `which` in options.jobs worker processes
/// (options.pair_timeout each), costliest first (the product of the parts'
/// hull vertex counts; ties keep their order), showing progress as `what`.
/// `done(k, result)` runs in the parent as each pair ends; a worker that
/// crashed, timed out or answered unreadably is an error result on its pair
/// only. `before_task(k)` runs in the worker first (tests' fault injection).
void solve_pairs_in_workers(std::vector<size_t> which, const std::function<PairJob(size_t)>& job,
                            const RunOptions& options,
                            const std::function<PairChecks(int, int)>& checks, const char* what,
                            const std::function<void(size_t, PairResult)>& done,
                            const std::function<void(size_t)>& before_task = {});

}  // namespace pd
