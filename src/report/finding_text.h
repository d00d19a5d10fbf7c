// One sentence per pair for people (JUnit messages, SARIF results, stderr).
#pragma once

#include <string>

#include "batch/run_result.h"
#include "report/review.h"

namespace pd {

/// Every sentence about a pair, rendered from its status, depth source and
/// bounds, so no output can contradict the numbers:
/// "interference: depth 0.53 mm > tolerance 0.1 mm; moving b by the depth along
/// (0, 0, 1) separates the pair" (convex pairs: the depth is a separating move);
/// "false_positive: overlap thickness 0.02 mm <= tolerance 0.05 mm (certified
/// between 0.02 and 0.03 mm)" (nonconvex pairs: no move is claimed);
/// "undecided: depth between 0.02 and 0.3 mm, tolerance 0.05 mm (why)"; with
/// the baseline state and suppression when set. Under tolerance auto the
/// pair's own band replaces `tolerance`, and a finding says what it rests on:
/// "false_positive: overlap thickness 0.08 mm <= tolerance 0.12 mm; a
/// tessellation artefact within the band of measured sag (bushing: bore r 20
/// mm, 32 segments, sag 0.0963 mm; pin: …)".
std::string finding_text(const PairResult& r, const std::vector<Part>& parts,
                         const PairReview& review, const std::string& units, double tolerance);

/// What a depth of this source is: "depth", "overlap thickness", "deepest vertex depth", …
std::string depth_meaning(const std::string& depth_source);

/// A B-rep pair's exact check in words: what the solids showed and what that
/// rests on ("the exact solids touch (confirmed on the exact solids)", "the
/// exact solids' overlap thickness is between 0.98 and 1.02 mm (certified by
/// the deflection bound)", "not confirmed on the exact solids (why)").
/// `depth_source` is the pair's: what a bracket widened from the meshes is of.
std::string exact_text(const ExactCheck& e, const std::string& depth_source,
                       const std::string& units);

/// Shortest round-trip-ish decimal for messages (%.6g).
std::string short_number(double x);

}  // namespace pd
