#include "work_queue.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cstdint>
#include <cstring>
#include <deque>
#include <stdexcept>

#include "termination.h"
#include "worker_limit.h"

namespace pd {

namespace {

using Clock = std::chrono::steady_clock;

bool write_all(int fd, const void* data, size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= static_cast<size_t>(w);
  }
  return true;
}

bool read_all(int fd, void* data, size_t n) {
  char* p = static_cast<char*>(data);
  while (n > 0) {
    const ssize_t r = ::read(fd, p, n);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) return false;
    p += r;
    n -= static_cast<size_t>(r);
  }
  return true;
}

[[noreturn]] void worker_loop(int in, int out, const TaskFn& task) {
  std::uint64_t index = 0;
  while (read_all(in, &index, sizeof index)) {
    const std::string payload = task(static_cast<size_t>(index));
    const std::uint64_t len = payload.size();
    if (!write_all(out, &index, sizeof index) || !write_all(out, &len, sizeof len) ||
        !write_all(out, payload.data(), payload.size()))
      break;
  }
  _exit(0);
}

// A worker holds up to kDepth tasks: the one it is computing and the next,
// already in its pipe, so it never waits on the parent between tasks.
constexpr size_t kDepth = 2;

struct Worker {
  pid_t pid = -1;
  int to = -1, from = -1;
  std::deque<size_t> tasks;   ///< sent, not yet answered; the front one is running
  Clock::time_point started;  ///< when the front task began (its answer clock)
};

/// Starts a worker; throws std::runtime_error (with errno's reason) if it cannot.
Worker spawn(const TaskFn& task, const std::vector<Worker>& others) {
  int down[2], up[2];
  if (pipe2(down, O_CLOEXEC) != 0)
    throw std::runtime_error(std::string("pipe() failed: ") + std::strerror(errno));
  if (pipe2(up, O_CLOEXEC) != 0) {
    const int err = errno;
    close(down[0]);
    close(down[1]);
    throw std::runtime_error(std::string("pipe() failed: ") + std::strerror(err));
  }
  // Signals blocked until the child is tracked: a termination signal finds
  // every worker, and a child never runs the parent's handler.
  const TerminationBlocked blocked;
  const pid_t pid = fork();
  if (pid < 0) {
    const int err = errno;
    for (int fd : {down[0], down[1], up[0], up[1]}) close(fd);
    throw std::runtime_error(std::string("fork() failed: ") + std::strerror(err));
  }
  if (pid == 0) {
    blocked.reset_in_child();
    close(down[1]);
    close(up[0]);
    for (const Worker& w : others) {  // a worker holds only its own pipes
      if (w.to >= 0) close(w.to);
      if (w.from >= 0) close(w.from);
    }
    worker_loop(down[0], up[1], task);
  }
  track_child(pid);
  close(down[0]);
  close(up[1]);
  Worker w;
  w.pid = pid;
  w.to = down[1];
  w.from = up[0];
  return w;
}

/// Ends a worker and says why it ended. Tasks it held but had not started go
/// back to `retry`; the running one is the caller's to report.
std::string reap(Worker& w, bool kill_it, std::deque<size_t>& retry) {
  if (kill_it) kill(w.pid, SIGKILL);
  close(w.to);
  close(w.from);
  int status = 0;
  std::string why = "worker exited";
  pid_t r;
  while ((r = waitpid(w.pid, &status, 0)) < 0 && errno == EINTR) {
  }
  untrack_child(w.pid);
  if (r == w.pid) {
    if (WIFSIGNALED(status))
      why = std::string("worker crashed (") + strsignal(WTERMSIG(status)) + ")";
    else if (WIFEXITED(status))
      why = "worker exited with code " + std::to_string(WEXITSTATUS(status));
  }
  for (size_t k = w.tasks.size(); k-- > 1;) retry.push_front(w.tasks[k]);
  w = Worker{};
  return why;
}

// Ignores SIGPIPE while it lives: a worker that dies must not kill the parent
// with SIGPIPE on the next write. The previous action comes back at the end.
class SigpipeIgnored {
 public:
  SigpipeIgnored() {
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigaction(SIGPIPE, &ignore, &previous_);
  }
  ~SigpipeIgnored() { sigaction(SIGPIPE, &previous_, nullptr); }
  SigpipeIgnored(const SigpipeIgnored&) = delete;
  SigpipeIgnored& operator=(const SigpipeIgnored&) = delete;

 private:
  struct sigaction previous_ {};
};

// The parent's side of one run: the workers, the tasks not yet sent, and
// those to send again because their worker died before starting them.
class Dispatcher {
 public:
  Dispatcher(const std::vector<size_t>& order, const QueueOptions& options, const TaskFn& task,
             const DoneFn& done)
      : order_(order), options_(options), task_(task), done_(done) {}
  // Ends every worker if the run is left by an exception (a `done` that
  // throws, e.g. on a closed output): none is left solving on its own.
  ~Dispatcher() {
    std::deque<size_t> none;
    for (Worker& w : workers_)
      if (w.pid >= 0) reap(w, true, none);
  }
  Dispatcher(const Dispatcher&) = delete;
  Dispatcher& operator=(const Dispatcher&) = delete;

  void run() {
    start_workers();
    for (Worker& w : workers_) feed(w);
    while (finished_ < order_.size()) poll_round();
    std::deque<size_t> none;
    for (Worker& w : workers_)
      if (w.pid >= 0) reap(w, false, none);  // closing its input ends the worker's loop
  }

 private:
  // As many workers as tasks, options.jobs and the open-file limit allow.
  // Fewer start (a fork or a pipe fails) with a warning; none is an error.
  void start_workers() {
    int jobs = std::max(1, std::min<int>(options_.jobs, static_cast<int>(order_.size())));
    std::string why;
    jobs = workers_within_fd_limit(jobs, why);
    for (int k = 0; k < jobs; ++k) {
      try {
        workers_.push_back(spawn(task_, workers_));
      } catch (const std::runtime_error& e) {
        if (workers_.empty()) throw;  // not even one: the caller must know
        why = "could start only " + std::to_string(workers_.size()) + " of " +
              std::to_string(jobs) + " worker processes (" + e.what() + ")";
        break;
      }
    }
    if (!why.empty() && options_.warn) options_.warn(why);
  }

  bool pending() const { return !retry_.empty() || next_ < order_.size(); }

  // Tops a worker up to kDepth tasks, replacing it if it died meanwhile.
  void feed(Worker& w) {
    while (w.tasks.size() < kDepth && pending()) {
      if (w.pid < 0) w = spawn(task_, workers_);
      const bool again = !retry_.empty();
      const std::uint64_t index = again ? retry_.front() : order_[next_];
      if (!write_all(w.to, &index, sizeof index)) {
        if (w.tasks.empty()) {  // it died idle: replace it and try again
          reap(w, true, retry_);
          continue;
        }
        return;  // its running task will report the death
      }
      again ? retry_.pop_front() : void(++next_);
      if (w.tasks.empty()) w.started = Clock::now();
      w.tasks.push_back(index);
    }
  }

  // Waits for an answer from any busy worker, or for the nearest task
  // timeout, and handles what came.
  void poll_round() {
    std::vector<pollfd> fds;
    std::vector<size_t> who;  // fds[f] is workers_[who[f]]'s answer pipe
    int wait_ms = -1;
    const auto now = Clock::now();
    for (size_t k = 0; k < workers_.size(); ++k) {
      if (workers_[k].tasks.empty()) continue;
      fds.push_back({workers_[k].from, POLLIN, 0});
      who.push_back(k);
      if (options_.task_timeout > 0) {
        const double left = options_.task_timeout -
                            std::chrono::duration<double>(now - workers_[k].started).count();
        const int ms = poll_timeout_ms(left);
        wait_ms = wait_ms < 0 ? ms : std::min(wait_ms, ms);
      }
    }
    const int ready = poll(fds.data(), fds.size(), wait_ms);
    if (ready < 0 && errno != EINTR) throw std::runtime_error("poll() failed");
    for (size_t f = 0; f < fds.size(); ++f) {
      Worker& w = workers_[who[f]];
      if (fds[f].revents & (POLLIN | POLLHUP | POLLERR)) {
        take_answer(w);
      } else if (options_.task_timeout > 0 &&
                 std::chrono::duration<double>(Clock::now() - w.started).count() >
                     options_.task_timeout) {
        time_out(w);
      }
    }
    // A worker replaced above may leave retried tasks that its own feed could
    // not place (it was full); idle workers take them.
    for (Worker& w : workers_)
      if (w.tasks.empty()) feed(w);
  }

  // The running task's answer (or the worker's death: a short read, or an
  // answer for another task, which a sound worker never sends).
  void take_answer(Worker& w) {
    const size_t running = w.tasks.front();
    std::uint64_t index = 0, len = 0;
    std::string payload;
    bool ok = read_all(w.from, &index, sizeof index) && read_all(w.from, &len, sizeof len);
    if (ok) {
      payload.resize(len);
      ok = read_all(w.from, payload.data(), len) && index == running;
    }
    ++finished_;
    if (ok) {
      w.tasks.pop_front();
      w.started = Clock::now();
      done_(running, true, payload);
    } else {
      done_(running, false, reap(w, true, retry_));
    }
    feed(w);
  }

  // The running task took too long: its worker is killed (a hung solver
  // cannot be interrupted otherwise) and replaced.
  void time_out(Worker& w) {
    const size_t running = w.tasks.front();
    reap(w, true, retry_);
    ++finished_;
    done_(running, false,
          "timed out after " + std::to_string(options_.task_timeout) + " s (worker killed)");
    feed(w);
  }

  const std::vector<size_t>& order_;
  const QueueOptions& options_;
  const TaskFn& task_;
  const DoneFn& done_;
  std::vector<Worker> workers_;
  size_t next_ = 0;           ///< order_[next_] is the next task never sent
  size_t finished_ = 0;       ///< tasks reported to done_
  std::deque<size_t> retry_;  ///< sent to a worker that died before starting them
};

}  // namespace

int poll_timeout_ms(double seconds_left) {
  if (!(seconds_left > 0)) return 0;
  return static_cast<int>(std::min(seconds_left * 1000.0 + 1.0, static_cast<double>(INT_MAX)));
}

void run_work_queue(const std::vector<size_t>& order, const QueueOptions& options,
                    const TaskFn& given_task, const DoneFn& done) {
  if (order.empty()) return;
  const TaskFn task = options.before_task ? TaskFn([&](size_t index) {
    options.before_task(index);
    return given_task(index);
  })
                                          : given_task;
  const SigpipeIgnored sigpipe_ignored;
  Dispatcher(order, options, task, done).run();
}

}  // namespace pd
