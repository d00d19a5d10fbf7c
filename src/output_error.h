// A report (or another output) that could not be delivered.
#pragma once

#include <stdexcept>

#include "user_error.h"

namespace pd {

/// The message names the output (option and path, or standard output) and the reason.
struct OutputError : UserError {
  using UserError::UserError;
};

}  // namespace pd
