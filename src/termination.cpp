#include "termination.h"

#include <fcntl.h>
#include <limits.h>
#include <sys/syscall.h>
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

constexpr int kMaxTempDirs = 4;  // a run's mesh stores (one each for a run and an HTML page)
char g_dir_path[kMaxTempDirs][PATH_MAX];
std::atomic<int> g_dir_fd[kMaxTempDirs];     // open O_DIRECTORY descriptor, -1 or 0 when free
std::atomic<int> g_dir_state[kMaxTempDirs];  // 0 free, 1 being filled, 2 tracked

constexpr int kSignals[] = {SIGTERM, SIGINT, SIGHUP};

// Removes the files of directory `fd` and the directory `path`, with system
// calls only (async-signal-safe: getdents64 lists without allocating).
void remove_temp_dir(int fd, const char* path) {
  alignas(8) static char buf[8192];
  for (;;) {
    lseek(fd, 0, SEEK_SET);
    const long n = syscall(SYS_getdents64, fd, buf, sizeof buf);
    if (n <= 0) break;
    bool removed = false;
    for (long at = 0; at < n;) {
      // struct linux_dirent64: d_ino (8), d_off (8), d_reclen (2), d_type (1), d_name.
      unsigned short reclen = 0;
      std::memcpy(&reclen, buf + at + 16, sizeof reclen);
      const char* name = buf + at + 19;
      if (std::strcmp(name, ".") != 0 && std::strcmp(name, "..") != 0)
        removed |= unlinkat(fd, name, 0) == 0;
      at += reclen;
    }
    if (!removed) break;  // nothing more it can remove
  }
  rmdir(path);
}

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
  for (int k = 0; k < kMaxTempDirs; ++k)
    if (g_dir_state[k].load() == 2) remove_temp_dir(g_dir_fd[k].load(), g_dir_path[k]);
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

void TrackedTempDir::track(const std::string& dir) {
  if (slot_ >= 0 || dir.size() >= PATH_MAX) return;
  const int fd = open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  for (int k = 0; k < kMaxTempDirs; ++k) {
    int free_slot = 0;
    if (g_dir_state[k].compare_exchange_strong(free_slot, 1)) {
      std::memcpy(g_dir_path[k], dir.c_str(), dir.size() + 1);
      g_dir_fd[k].store(fd);
      g_dir_state[k].store(2);
      slot_ = k;
      return;
    }
  }
  close(fd);
}

TrackedTempDir::~TrackedTempDir() {
  if (slot_ < 0) return;
  const int fd = g_dir_fd[slot_].load();
  g_dir_state[slot_].store(0);
  close(fd);
}

}  // namespace pd
