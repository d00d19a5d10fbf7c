#include "batch/progress.h"

#include <unistd.h>

#include <string>
#include <utility>

namespace pd {

Progress::Progress(size_t total, bool quiet, std::string what, std::FILE* out)
    : total_(total),
      quiet_(quiet || total == 0),
      tty_(isatty(fileno(out))),
      what_(std::move(what)),
      out_(out) {
  start_ = last_ = std::chrono::steady_clock::now();
}

void Progress::tick(size_t n) {
  const std::lock_guard<std::mutex> lock(mutex_);
  done_ += n;
  draw(false);
}

void Progress::draw(bool force) {
  if (quiet_) return;
  const auto now = std::chrono::steady_clock::now();
  const double since_last = std::chrono::duration<double>(now - last_).count();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  // A terminal gets ~10 redraws a second; a log gets a line per 10% or per
  // 10 s, and none in a stage's first second (a short stage needs no progress).
  const bool due = tty_ ? since_last > 0.1
                        : elapsed >= 1.0 && (done_ * 10 / total_ > last_reported_ * 10 / total_ ||
                                             since_last > 10.0);
  if (!force && !due) return;
  last_ = now;
  last_reported_ = done_;
  const double rate = elapsed > 0 ? done_ / elapsed : 0.0;
  const double eta = rate > 0 ? (total_ - done_) / rate : 0.0;
  if (tty_) {
    const int width = 30, filled = static_cast<int>(width * done_ / total_);
    std::fprintf(out_, "\r[%s%s] %zu/%zu %s  %.0f/s  ETA %.0f s ", std::string(filled, '#').c_str(),
                 std::string(width - filled, ' ').c_str(), done_, total_, what_.c_str(), rate, eta);
  } else {
    std::fprintf(out_, "pdcheck: %zu/%zu %s (%zu%%), %.0f %s/s, ETA %.0f s\n", done_, total_,
                 what_.c_str(), done_ * 100 / total_, rate, what_.c_str(), eta);
  }
  std::fflush(out_);
}

void Progress::finish() {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (quiet_) return;
  if (tty_) {
    draw(true);
    std::fputc('\n', out_);
  }
}

}  // namespace pd
