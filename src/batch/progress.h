// Progress on stderr: a live bar on a terminal, sparse plain lines otherwise.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdio>

namespace pd {

class Progress {
 public:
  Progress(size_t total, bool quiet, std::FILE* out = stderr);
  void tick();    ///< one more pair done
  void finish();  ///< end the bar's line

 private:
  void draw(bool force);
  size_t total_, done_ = 0;
  bool quiet_, tty_;
  std::FILE* out_;
  std::chrono::steady_clock::time_point start_, last_;
  size_t last_reported_ = 0;
};

}  // namespace pd
