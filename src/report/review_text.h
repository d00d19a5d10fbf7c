// The review for people on stderr, and the --write-suppressions file.
#pragma once

#include <string>

#include "report/writer.h"

namespace pd {

/// Lines for stderr: each finding that fails the run (at most 20, then a
/// count), each suppression issue, and the baseline counts when one was given.
std::string review_lines(const ReportInput& in);

/// A starting suppressions file for the run's findings at or above the bar
/// (interference and clearance violations for `new` and `none`), keeping the
/// entries of the current --suppressions file for the same pairs.
std::string suppressions_to_write(const ReportInput& in, const std::string& today);

}  // namespace pd
