#include "memory_limit.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#if defined(__SANITIZE_ADDRESS__)
#define PD_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PD_ADDRESS_SANITIZER 1
#endif
#endif

namespace pd {

namespace {

constexpr double kMB = 1024.0 * 1024.0;

/// cgroup v2's limit for this process ("max" or absent: none), in MB; 0 if none.
double cgroup_limit_mb() {
  std::ifstream in("/sys/fs/cgroup/memory.max");
  std::string word;
  if (!(in >> word) || word == "max") return 0.0;
  try {
    return std::stod(word) / kMB;
  } catch (const std::exception&) {
    return 0.0;
  }
}

}  // namespace

double available_memory_mb() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  double mb = pages > 0 && page > 0 ? double(pages) * double(page) / kMB : 0.0;
  const double cgroup = cgroup_limit_mb();
  if (cgroup > 0.0 && (mb == 0.0 || cgroup < mb)) mb = cgroup;
  return mb;
}

double memory_share_mb(double available_mb, int processes) {
  if (!(available_mb > 0.0)) return 0.0;
  return available_mb / 2.0 / std::max(1, processes);
}

double memory_budget_mb(double available_mb) {
  if (!(available_mb > 0.0)) return 1024.0;
  return std::clamp(available_mb / 8.0, 256.0, 1024.0);
}

double parse_memory_mb(const std::string& text) {
  size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  std::string unit = text.substr(used);
  if (!unit.empty() && (unit.back() == 'B' || unit.back() == 'b') && unit.size() == 2)
    unit.pop_back();
  double scale = -1.0;
  if (unit.empty() || unit == "M" || unit == "m")
    scale = 1.0;
  else if (unit == "K" || unit == "k")
    scale = 1.0 / 1024.0;
  else if (unit == "G" || unit == "g")
    scale = 1024.0;
  else if (unit == "T" || unit == "t")
    scale = 1024.0 * 1024.0;
  if (used == 0 || scale < 0 || !(v > 0.0) || !std::isfinite(v * scale))
    throw std::invalid_argument("--memory: \"" + text +
                                "\" is not an amount of memory (e.g. 512M, 2G, or a number of MB)");
  return v * scale;
}

bool can_cap_address_space() {
#ifdef PD_ADDRESS_SANITIZER
  return false;
#else
  return true;
#endif
}

#ifndef PD_ADDRESS_SANITIZER
namespace {
/// Bytes of address space this process maps now (/proc/self/statm, first field).
double mapped_bytes() {
  std::ifstream in("/proc/self/statm");
  double pages = 0.0;
  if (!(in >> pages)) return -1.0;
  return pages * double(sysconf(_SC_PAGESIZE));
}

}  // namespace
#endif

bool cap_address_space_growth(double mb) {
#ifdef PD_ADDRESS_SANITIZER
  (void)mb;
  return false;
#else
  if (!(mb > 0.0) || !std::isfinite(mb)) return false;
  const double now = mapped_bytes();
  if (now < 0.0) return false;
  rlimit lim{};
  if (getrlimit(RLIMIT_AS, &lim) != 0) return false;
  const double wanted = now + mb * kMB;
  if (lim.rlim_max != RLIM_INFINITY && wanted >= double(lim.rlim_max)) return false;
  if (lim.rlim_cur != RLIM_INFINITY && wanted >= double(lim.rlim_cur))
    return false;  // tighter already
  lim.rlim_cur = static_cast<rlim_t>(wanted);
  return setrlimit(RLIMIT_AS, &lim) == 0;
#endif
}

}  // namespace pd
