#include "batch/pair_workers.h"

#include <algorithm>
#include <memory>

#include "batch/progress.h"
#include "solve/ipopt_local.h"
#include "work_queue.h"

namespace pd {

void solve_pairs_in_workers(std::vector<size_t> which, const std::function<PairJob(size_t)>& job,
                            const RunOptions& options,
                            const std::function<PairChecks(int, int)>& checks, const char* what,
                            const std::function<void(size_t, PairResult)>& done,
                            const std::function<void(size_t)>& before_task) {
  // The costliest first: the pool's tail is then short pairs, not one long one.
  auto cost = [&](size_t k) {
    const PairJob j = job(k);
    return j.part_a->hull_vertex_count() * j.part_b->hull_vertex_count();
  };
  std::vector<long> costs(which.size());
  for (size_t n = 0; n < which.size(); ++n) costs[n] = cost(which[n]);
  std::vector<size_t> by_cost(which.size());
  for (size_t n = 0; n < by_cost.size(); ++n) by_cost[n] = n;
  std::stable_sort(by_cost.begin(), by_cost.end(),
                   [&](size_t x, size_t y) { return costs[x] > costs[y]; });
  std::vector<size_t> order(which.size());
  for (size_t n = 0; n < order.size(); ++n) order[n] = which[by_cost[n]];

  Progress progress(order.size(), options.quiet, what);
  std::unique_ptr<IpoptLocalSolver> ipopt;  // created in each worker on first use
  auto task = [&](size_t k) {
    if (!ipopt) ipopt = std::make_unique<IpoptLocalSolver>();
    const PairJob j = job(k);
    return encode_pair_result(solve_part_pair(j.a, *j.part_a, j.b, *j.part_b, options.solver,
                                              options.tolerance, *ipopt, checks(j.a, j.b)));
  };
  auto answer = [&](size_t k, bool ok, const std::string& payload) {
    const PairJob j = job(k);
    done(k, pair_result_from_worker(ok, payload, j.a, j.b, method_name(options.solver.method)));
    progress.tick();
  };
  QueueOptions queue{options.jobs, options.pair_timeout, options.on_warning};
  if (before_task) queue.before_task = before_task;
  run_work_queue(order, queue, task, answer);
  progress.finish();
}

}  // namespace pd
