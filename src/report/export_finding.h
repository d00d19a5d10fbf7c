// One finding as the exports (--csv, --bcf) show it, read from the run and its
// review in one place: where a field comes from changes here only (finding
// groups, and `at` on every finding, are made elsewhere).
#pragma once

#include <optional>
#include <string>

#include "report/writer.h"

namespace pd {

/// Exported pairs: every pair that is not `separated` (false positives,
/// interferences, clearance violations, undecided and failed pairs).
bool exported(Status s);

struct ExportFinding {
  size_t index = 0;  ///< into run.pairs
  const PairResult* pair = nullptr;
  const PairReview* review = nullptr;
  std::string a, b, fingerprint;
  std::optional<double> depth, margin;  ///< decided pairs (not `error`), as the report has them
  std::optional<double> tolerance;      ///< the one the pair was decided against
  std::optional<Vec3> at;               ///< where the depth was found, when the report says
  std::string group;                    ///< the finding's group id ("": none)
  std::string baseline_state;           ///< with --baseline ("": none)
  std::string suppression;              ///< the reason of the suppression that holds ("": none)
  std::string message;                  ///< the finding's sentence (report/finding_text.h)
};

/// Pair `k` of the run as the exports show it.
ExportFinding export_finding(const ReportInput& in, size_t k);

}  // namespace pd
