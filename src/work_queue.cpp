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
  // A worker that dies must not kill the parent with SIGPIPE on the next write.
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  struct sigaction previous {};
  sigaction(SIGPIPE, &ignore, &previous);

  int jobs = std::max(1, std::min<int>(options.jobs, static_cast<int>(order.size())));
  std::string why;
  jobs = workers_within_fd_limit(jobs, why);
  std::vector<Worker> workers;
  // Ends every worker if this function is left by an exception (a `done`
  // that throws, e.g. on a closed output): none is left solving on its own.
  struct Cleanup {
    std::vector<Worker>& workers;
    const struct sigaction& previous;
    ~Cleanup() {
      std::deque<size_t> none;
      for (Worker& w : workers)
        if (w.pid >= 0) reap(w, true, none);
      sigaction(SIGPIPE, &previous, nullptr);
    }
  } cleanup{workers, previous};
  for (int k = 0; k < jobs; ++k) {
    try {
      workers.push_back(spawn(task, workers));
    } catch (const std::runtime_error& e) {
      if (workers.empty()) throw;  // not even one: the caller must know
      why = "could start only " + std::to_string(workers.size()) + " of " + std::to_string(jobs) +
            " worker processes (" + e.what() + ")";
      break;
    }
  }
  if (!why.empty() && options.warn) options.warn(why);
  size_t next = 0, finished = 0;
  std::deque<size_t> retry;  // sent to a worker that died before starting them
  auto pending = [&] { return !retry.empty() || next < order.size(); };

  // Tops a worker up to kDepth tasks, replacing it if it died meanwhile.
  auto feed = [&](Worker& w) {
    while (w.tasks.size() < kDepth && pending()) {
      if (w.pid < 0) w = spawn(task, workers);
      const bool again = !retry.empty();
      const std::uint64_t index = again ? retry.front() : order[next];
      if (!write_all(w.to, &index, sizeof index)) {
        if (w.tasks.empty()) {  // it died idle: replace it and try again
          reap(w, true, retry);
          continue;
        }
        return;  // its running task will report the death
      }
      again ? retry.pop_front() : void(++next);
      if (w.tasks.empty()) w.started = Clock::now();
      w.tasks.push_back(index);
    }
  };
  for (Worker& w : workers) feed(w);

  while (finished < order.size()) {
    std::vector<pollfd> fds;
    std::vector<size_t> who;
    int wait_ms = -1;
    const auto now = Clock::now();
    for (size_t k = 0; k < workers.size(); ++k) {
      if (workers[k].tasks.empty()) continue;
      fds.push_back({workers[k].from, POLLIN, 0});
      who.push_back(k);
      if (options.task_timeout > 0) {
        const double left =
            options.task_timeout - std::chrono::duration<double>(now - workers[k].started).count();
        const int ms = poll_timeout_ms(left);
        wait_ms = wait_ms < 0 ? ms : std::min(wait_ms, ms);
      }
    }
    const int ready = poll(fds.data(), fds.size(), wait_ms);
    if (ready < 0 && errno != EINTR) throw std::runtime_error("poll() failed");
    for (size_t f = 0; f < fds.size(); ++f) {
      Worker& w = workers[who[f]];
      const size_t running = w.tasks.front();
      if (fds[f].revents & (POLLIN | POLLHUP | POLLERR)) {
        std::uint64_t index = 0, len = 0;
        std::string payload;
        bool ok = read_all(w.from, &index, sizeof index) && read_all(w.from, &len, sizeof len);
        if (ok) {
          payload.resize(len);
          ok = read_all(w.from, payload.data(), len) && index == running;
        }
        ++finished;
        if (ok) {
          w.tasks.pop_front();
          w.started = Clock::now();
          done(running, true, payload);
        } else {
          done(running, false, reap(w, true, retry));
        }
        feed(w);
      } else if (options.task_timeout > 0 &&
                 std::chrono::duration<double>(Clock::now() - w.started).count() >
                     options.task_timeout) {
        reap(w, true, retry);
        ++finished;
        done(running, false,
             "timed out after " + std::to_string(options.task_timeout) + " s (worker killed)");
        feed(w);
      }
    }
    // A worker replaced above may leave retried tasks that its own feed could
    // not place (it was full); idle workers take them.
    for (Worker& w : workers)
      if (w.tasks.empty()) feed(w);
  }
  std::deque<size_t> none;
  for (Worker& w : workers)
    if (w.pid >= 0) reap(w, false, none);  // closing its input ends the worker's loop
}

}  // namespace pd
