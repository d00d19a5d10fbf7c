#include "termination.h"

#include <limits.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <cstring>

namespace pd {

namespace {

// Fixed tables, not containers: the handler may only read memory that no
// allocation can move, with lock-free atomics (async-signal-safe).
constexpr int kMaxChildren = 8192;  // --jobs is at most 4096, plus helpers
std::atomic<pid_t> g_children[kMaxChildren];

constexpr int kMaxTemps = 8;  // output files are written one at a time
char g_temp_path[kMaxTemps][PATH_MAX];
std::atomic<int> g_temp_state[kMaxTemps];  // 0 free, 1 being filled, 2 tracked

constexpr int kSignals[] = {SIGTERM, SIGINT, SIGHUP};

void sleep_ms(long ms) {
  timespec t{ms / 1000, (ms % 1000) * 1000000L};
  nanosleep(&t, nullptr);
}

void on_termination(int sig) {
  for (auto& c : g_children)
    if (const pid_t pid = c.load()) kill(pid, sig);
  // A worker ends at once on the forwarded signal (default disposition); one
  // that has not after ~2 s is killed, so the handler itself cannot hang.
  for (int round = 0; round <= 200; ++round) {
    bool left = false;
    for (auto& c : g_children) {
      const pid_t pid = c.load();
      if (!pid) continue;
      if (round == 200) kill(pid, SIGKILL);
      const pid_t r = waitpid(pid, nullptr, round == 200 ? 0 : WNOHANG);
      if (r == pid || r < 0)
        c.store(0);
      else
        left = true;
    }
    if (!left) break;
    sleep_ms(10);
  }
  for (int k = 0; k < kMaxTemps; ++k)
    if (g_temp_state[k].load() == 2) unlink(g_temp_path[k]);
  _exit(128 + sig);
}

sigset_t termination_set() {
  sigset_t s;
  sigemptyset(&s);
  for (int sig : kSignals) sigaddset(&s, sig);
  return s;
}

}  // namespace

void install_termination_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_termination;
  sa.sa_mask = termination_set();  // one handler at a time
  for (int sig : kSignals) sigaction(sig, &sa, nullptr);
}

void track_child(pid_t pid) {
  for (auto& c : g_children) {
    pid_t free_slot = 0;
    if (c.compare_exchange_strong(free_slot, pid)) return;
  }
}

void untrack_child(pid_t pid) {
  for (auto& c : g_children) {
    pid_t mine = pid;
    if (c.compare_exchange_strong(mine, 0)) return;
  }
}

TerminationBlocked::TerminationBlocked() {
  const sigset_t s = termination_set();
  pthread_sigmask(SIG_BLOCK, &s, &old_);
}

TerminationBlocked::~TerminationBlocked() {
  pthread_sigmask(SIG_SETMASK, &old_, nullptr);
}

void TerminationBlocked::reset_in_child() const {
  for (int sig : kSignals) signal(sig, SIG_DFL);
  pthread_sigmask(SIG_SETMASK, &old_, nullptr);
}

void TrackedTempFile::track(const std::string& path) {
  if (slot_ >= 0 || path.size() >= PATH_MAX) return;  // too long: it could not exist
  for (int k = 0; k < kMaxTemps; ++k) {
    int free_slot = 0;
    if (g_temp_state[k].compare_exchange_strong(free_slot, 1)) {
      std::memcpy(g_temp_path[k], path.c_str(), path.size() + 1);
      g_temp_state[k].store(2);
      slot_ = k;
      return;
    }
  }
}

TrackedTempFile::~TrackedTempFile() {
  if (slot_ >= 0) g_temp_state[slot_].store(0);
}

}  // namespace pd
