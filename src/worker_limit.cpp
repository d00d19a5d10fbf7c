#include "worker_limit.h"

#include <dirent.h>
#include <sys/resource.h>

#include <algorithm>

namespace pd {

namespace {

// Descriptors kept free for everything else the parent opens while workers
// run: the output's temporary file, stdio, libraries that open files lazily.
constexpr long kFdReserve = 32;

long open_fds() {
  DIR* d = opendir("/proc/self/fd");
  if (!d) return 64;  // no /proc: a generous guess
  long n = 0;
  while (readdir(d)) ++n;
  closedir(d);
  return n - 3;  // ".", ".." and the directory's own descriptor
}

}  // namespace

int workers_within_fd_limit(int wanted, std::string& why) {
  why.clear();
  rlimit lim{};
  if (getrlimit(RLIMIT_NOFILE, &lim) != 0) return wanted;
  const long used = open_fds();
  const long needed = used + 2L * wanted + 2 + kFdReserve;
  if (lim.rlim_cur != RLIM_INFINITY && static_cast<long>(lim.rlim_cur) < needed) {
    rlimit raised = lim;
    raised.rlim_cur = lim.rlim_max == RLIM_INFINITY
                          ? needed
                          : std::min<rlim_t>(lim.rlim_max, static_cast<rlim_t>(needed));
    if (setrlimit(RLIMIT_NOFILE, &raised) == 0) lim = raised;
  }
  if (lim.rlim_cur == RLIM_INFINITY || static_cast<long>(lim.rlim_cur) >= needed) return wanted;
  const long fit = (static_cast<long>(lim.rlim_cur) - used - 2 - kFdReserve) / 2;
  const int allowed = static_cast<int>(std::clamp<long>(fit, 1, wanted));
  why = std::to_string(wanted) + " worker processes need about " + std::to_string(needed) +
        " open files but the limit is " + std::to_string(lim.rlim_cur) + " (ulimit -n): running " +
        std::to_string(allowed);
  return allowed;
}

}  // namespace pd
