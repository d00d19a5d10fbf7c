// The process work queue on its own: every task ends exactly once, with its
// own payload, whatever the workers do.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <map>
#include <set>

#include "work_queue.h"

using namespace pd;

namespace {

struct Ended {
  std::map<size_t, std::string> payload, reason;
  int calls = 0;
};

Ended run(size_t n, int jobs, double timeout, const TaskFn& task) {
  std::vector<size_t> order(n);
  for (size_t k = 0; k < n; ++k) order[k] = n - 1 - k;  // not in index order
  Ended e;
  run_work_queue(order, {jobs, timeout, {}}, task, [&](size_t k, bool ok, const std::string& s) {
    ++e.calls;
    (ok ? e.payload : e.reason)[k] = s;
  });
  return e;
}

std::string square(size_t k) {
  return std::to_string(k * k);
}

}  // namespace

TEST(WorkQueue, EveryTaskEndsOnceWithItsPayload) {
  for (int jobs : {1, 2, 5}) {
    const Ended e = run(200, jobs, 0.0, square);
    EXPECT_EQ(e.calls, 200);
    ASSERT_EQ(e.payload.size(), 200u) << jobs;
    for (const auto& [k, s] : e.payload) EXPECT_EQ(s, square(k));
  }
}

TEST(WorkQueue, CrashesCostOnlyTheTasksThatCrash) {
  // Tasks 7 and 6 crash back to back (6 is sent next, queued behind 7 in the
  // same worker), 0 crashes last: queued tasks behind a crash are not lost.
  const std::set<size_t> crashing = {0, 6, 7, 30};
  for (int jobs : {1, 2, 3}) {
    const Ended e = run(40, jobs, 0.0, [&](size_t k) {
      if (crashing.count(k)) std::abort();
      return square(k);
    });
    EXPECT_EQ(e.calls, 40) << jobs;
    ASSERT_EQ(e.reason.size(), crashing.size()) << jobs;
    for (const auto& [k, why] : e.reason) {
      EXPECT_TRUE(crashing.count(k)) << k;
      EXPECT_NE(why.find("worker crashed"), std::string::npos) << why;
    }
    EXPECT_EQ(e.payload.size(), 40 - crashing.size());
    for (const auto& [k, s] : e.payload) EXPECT_EQ(s, square(k));
  }
}

TEST(WorkQueue, TheTestHookRunsInTheWorkerBeforeEachTask) {
  // Fault injection (QueueOptions::before_task): a crash there costs only its
  // task, and the hook runs in the worker, not in the parent.
  const pid_t parent = getpid();
  QueueOptions options{2, 0.0, {}};
  options.before_task = [parent](size_t k) {
    if (getpid() == parent || k == 3) std::abort();
  };
  std::map<size_t, std::string> payload, reason;
  run_work_queue({0, 1, 2, 3, 4, 5}, options, square,
                 [&](size_t k, bool ok, const std::string& s) { (ok ? payload : reason)[k] = s; });
  ASSERT_EQ(reason.size(), 1u);
  EXPECT_NE(reason[3].find("worker crashed"), std::string::npos) << reason[3];
  EXPECT_EQ(payload.size(), 5u);
  for (const auto& [k, s] : payload) EXPECT_EQ(s, square(k));
}

TEST(WorkQueue, TimeoutKillsOnlyTheSlowTask) {
  for (int jobs : {1, 2}) {
    const Ended e = run(12, jobs, 0.3, [](size_t k) {
      if (k == 5) sleep(30);  // far past the timeout
      return square(k);
    });
    EXPECT_EQ(e.calls, 12);
    ASSERT_EQ(e.reason.size(), 1u);
    EXPECT_NE(e.reason.at(5).find("timed out"), std::string::npos) << e.reason.at(5);
    EXPECT_EQ(e.payload.size(), 11u);
  }
}

TEST(WorkQueue, MoreWorkersThanTasks) {
  const Ended e = run(3, 8, 0.0, square);
  EXPECT_EQ(e.payload.size(), 3u);
  EXPECT_EQ(e.calls, 3);
}
