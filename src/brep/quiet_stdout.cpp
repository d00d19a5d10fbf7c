#include "brep/quiet_stdout.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace pd {

QuietStdout::QuietStdout() {
  std::cout.flush();
  std::fflush(stdout);
  const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  if (null < 0) return;
  saved_ = ::fcntl(1, F_DUPFD_CLOEXEC, 3);
  if (saved_ >= 0) ::dup2(null, 1);
  ::close(null);
}

QuietStdout::~QuietStdout() {
  if (saved_ < 0) return;
  std::cout.flush();
  std::fflush(stdout);
  ::dup2(saved_, 1);
  ::close(saved_);
}

}  // namespace pd
