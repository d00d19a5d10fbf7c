// Bad input to the report stage (a baseline or suppressions file): exit code 2.
#pragma once

#include <stdexcept>
#include <string>

#include "user_error.h"

namespace pd {

/// The message names the file and the JSON path: "s.json: $.suppressions[2].reason: …".
struct ReportInputError : UserError {
  using UserError::UserError;
};

}  // namespace pd
