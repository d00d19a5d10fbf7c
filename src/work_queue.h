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
  /// Told when the queue runs fewer workers than `jobs` (open-file or process limits).
  std::function<void(const std::string&)> warn;
  /// Tests only (fault injection): runs in the worker before task `index`, to
  /// make it crash or stall as a solver or a mesh reader could. The product
  /// never sets it.
  std::function<void(size_t index)> before_task = {};
};

/// Runs in a worker: computes task `index` and returns its encoded result.
using TaskFn = std::function<std::string(size_t index)>;
/// Runs in the parent as each task ends: payload on success, else the reason
/// (worker crashed, timed out) and an empty payload.
using DoneFn = std::function<void(size_t index, bool ok, const std::string& payload_or_reason)>;

/// Runs the tasks in `order` (largest first balances best), replacing workers
/// that crash or time out. Returns when every task has ended. If `done`
/// throws, the workers are killed and reaped and the exception goes on. The
/// workers are tracked for termination signals (termination.h).
void run_work_queue(const std::vector<size_t>& order, const QueueOptions& options,
                    const TaskFn& task, const DoneFn& done);

/// Milliseconds for poll() to wait when the nearest task timeout is
/// `seconds_left` away: rounded up, at least 0, at most INT_MAX (~24.8 days;
/// the loop then waits again), so a long timeout cannot overflow into a busy poll.
int poll_timeout_ms(double seconds_left);

}  // namespace pd
