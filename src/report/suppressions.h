// Reviewed suppressions (--suppressions FILE): an enumerated list of accepted
// findings, each a pair of part ids with the reason it is accepted. Format:
// docs/ci.md and docs/suppressions.schema.json.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "results/pair_result.h"

namespace pd {

struct Suppression {
  std::string a, b, fingerprint;    ///< the pair (no globs: ids name parts exactly)
  std::string reason;               ///< required, non-empty
  std::string owner, expires;       ///< optional; expires as YYYY-MM-DD, holding through that day
  std::optional<double> max_depth;  ///< holds while depth <= max_depth
  std::string comment;              ///< free text (--write-suppressions fills it in)
  std::string where;                ///< "$.suppressions[2]", for messages
  /// Set for an expected-contact rule (report/expected_rules.h): its name.
  /// Such an entry holds for every pair the rule covers, not one fingerprint.
  std::string rule;
};

struct Suppressions {
  std::string path;
  std::vector<Suppression> entries;
  std::map<std::string, size_t> by_fingerprint;  ///< index into entries
};

/// Throws ReportInputError naming the file and JSON path: unknown keys, a
/// missing or empty reason, a bad date, a negative max_depth, a pair of a part
/// with itself, a pair listed twice.
Suppressions parse_suppressions(const std::string& text, const std::string& path);
Suppressions load_suppressions(const std::string& path);

/// Whether a suppression holds for a finding of this depth on `today`
/// (YYYY-MM-DD): expired the day after `expires`, exceeded past `max_depth`.
enum class Hold { kHolds, kExpired, kExceeded };
Hold check_suppression(const Suppression& s, double depth, const std::string& today);

/// True for a real calendar date written YYYY-MM-DD.
bool is_iso_date(const std::string& s);
/// Today's date in UTC, YYYY-MM-DD.
std::string utc_today();

/// A starting suppressions file: one entry per given finding, with an empty
/// reason for a reviewer to fill in (the file is rejected until then) and a
/// comment saying what was found. An existing entry for the pair (`keep`) is
/// carried over as it is.
struct FindingToSuppress {
  std::string a, b, status;
  double depth = 0.0;
  std::string depth_name = "depth";  ///< what the depth is (finding_text.h, depth_meaning)
  const Suppression* keep = nullptr;
};
std::string suppressions_file_text(const std::vector<FindingToSuppress>& findings,
                                   const std::string& units, const std::string& today);

}  // namespace pd
