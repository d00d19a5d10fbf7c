// Standard output closed to what Open CASCADE prints past its messenger, for
// the life of a scope (internal to src/brep).
#pragma once

namespace pd {

/// While alive, file descriptor 1 is /dev/null (what was buffered is written
/// first); then it is the original again. Not thread-safe: B-rep files are read
/// in loader processes of one thread.
class QuietStdout {
 public:
  QuietStdout();
  ~QuietStdout();
  QuietStdout(const QuietStdout&) = delete;
  QuietStdout& operator=(const QuietStdout&) = delete;

 private:
  int saved_ = -1;
};

}  // namespace pd
