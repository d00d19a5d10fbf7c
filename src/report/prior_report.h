// Reads an old report for --reuse (batch/reuse.h): its settings hash, its parts'
// content hashes and its solved pairs.
#pragma once

#include <string>

#include "batch/reuse.h"
#include "report/input_error.h"
#include "report/prior_settings.h"

namespace pd {

/// Throws ReportInputError (exit 2) naming the file and what is wrong, e.g. a
/// report written without content hashes. `settings`, when given, gets the
/// report's unit, tolerance and method (check_prior_settings).
PriorResults load_prior_report(const std::string& path, PriorSettings* settings = nullptr);

}  // namespace pd
