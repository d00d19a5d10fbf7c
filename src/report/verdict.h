// The run's verdict in words, from a JSON report's summary: pass, fail or
// incomplete, and the counts behind it. The HTML page's banner and the
// terminal's table say it; an incomplete run (exit 3) never reads as a pass.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace pd {

struct Verdict {
  std::string state;     ///< "pass" (exit 0), "fail" (exit 1), "incomplete" (exit 3 or 2)
  std::string headline;  ///< "FAIL: 1 interference (exit code 1)"
  std::string counts;    ///< "1 interference, 3 false positives, 2 separated of 6 candidate pairs"
};

/// The verdict of a report's `summary` (docs/report-format.md): its
/// `exit_code` decides the state (a summary without one: interference fails,
/// an error, undecided or unchecked pair or an unusable part makes it
/// incomplete); `failing` and `fail_on` say what fails when the run's review
/// has them.
Verdict run_verdict(const nlohmann::ordered_json& summary);

}  // namespace pd
