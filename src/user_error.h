// A failure the user can fix: bad input or usage, or an output that cannot be
// written. The CLI says its message ("pdcheck: error: ...") and exits with its
// code; every such error type of the library derives from it.
#pragma once

#include <stdexcept>
#include <string>

#include "exit_code.h"

namespace pd {

class UserError : public std::runtime_error {
 public:
  explicit UserError(const std::string& what, ExitCode code = kExitBadInput)
      : std::runtime_error(what), code_(code) {}
  ExitCode exit_code() const noexcept { return code_; }

 private:
  ExitCode code_;
};

}  // namespace pd
