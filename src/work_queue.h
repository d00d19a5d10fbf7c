// A process work queue: tasks run in forked worker processes fed from one queue.
//
// Processes, not threads: Debian's Ipopt 3.11 with MUMPS is not thread-safe, and
// a crash or a hang in one solve or one mesh reader must cost only that task. Workers are forked
// after the parent has built everything the tasks need, so a task is sent as an index.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace pd {

struct QueueOptions {
  int jobs = 1;               ///< worker processes (>= 1)
  double task_timeout = 0.0;  ///< seconds; 0 = none. A worker past it is killed.
};

/// Runs in a worker: computes task `index` and returns its encoded result.
using TaskFn = std::function<std::string(size_t index)>;
/// Runs in the parent as each task ends: payload on success, else the reason
/// (worker crashed, timed out) and an empty payload.
using DoneFn = std::function<void(size_t index, bool ok, const std::string& payload_or_reason)>;

/// Runs the tasks in `order` (largest first balances best), replacing workers
/// that crash or time out. Returns when every task has ended.
void run_work_queue(const std::vector<size_t>& order, const QueueOptions& options,
                    const TaskFn& task, const DoneFn& done);

}  // namespace pd
