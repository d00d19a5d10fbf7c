// Progress on stderr: a live bar on a terminal, sparse plain lines otherwise.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <mutex>
#include <string>

namespace pd {

class Progress {
 public:
  /// `what` names the items counted ("parts", "pairs").
  Progress(size_t total, bool quiet, std::string what = "pairs", std::FILE* out = stderr);
  void tick(size_t n = 1);  ///< n more items done; safe to call from several threads
  void finish();            ///< end the bar's line

 private:
  void draw(bool force);
  std::mutex mutex_;
  size_t total_, done_ = 0;
  bool quiet_, tty_;
  std::string what_;
  std::FILE* out_;
  std::chrono::steady_clock::time_point start_, last_;
  size_t last_reported_ = 0;
};

}  // namespace pd
