// A report (or another output) that could not be delivered.
#pragma once

#include <stdexcept>

namespace pd {

/// The message names the output (option and path, or standard output) and the reason.
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace pd
