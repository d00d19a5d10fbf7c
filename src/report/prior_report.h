// Reads an old report for --reuse (batch/reuse.h): its settings hash, its parts'
// content hashes and its solved pairs.
#pragma once

#include <string>

#include "batch/reuse.h"
#include "report/input_error.h"

namespace pd {

/// Throws ReportInputError (exit 2) naming the file and what is wrong, e.g. a
/// report written without content hashes.
PriorResults load_prior_report(const std::string& path);

}  // namespace pd
