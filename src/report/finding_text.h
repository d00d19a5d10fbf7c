// One sentence per pair for people (JUnit messages, SARIF results, stderr).
#pragma once

#include <string>

#include "batch/run_result.h"
#include "report/review.h"

namespace pd {

/// "interference: depth 0.53 mm > tolerance 0.1 mm; moving b by the depth along
/// (0, 0, 1) separates the pair" (with the baseline state and suppression when set).
std::string finding_text(const PairResult& r, const std::vector<Part>& parts,
                         const PairReview& review, const std::string& units, double tolerance);

/// Shortest round-trip-ish decimal for messages (%.6g).
std::string short_number(double x);

}  // namespace pd
