// Comparing a run with a previous report (--baseline): which findings are new,
// unchanged, updated, gone (absent) or not knowable now (unknown). docs/ci.md.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "batch/run_result.h"
#include "report/input_error.h"
#include "report/prior_settings.h"

namespace pd {

enum class BaselineState { kNew, kUnchanged, kUpdated, kAbsent, kUnknown };
const char* baseline_state_name(BaselineState s);
inline constexpr BaselineState kBaselineStates[] = {BaselineState::kNew, BaselineState::kUnchanged,
                                                    BaselineState::kUpdated, BaselineState::kAbsent,
                                                    BaselineState::kUnknown};

/// A finding of the baseline report (false_positive, interference or clearance_violation).
struct BaselineFinding {
  std::string a, b, fingerprint, status;
  double depth = 0.0;
};

struct Baseline {
  std::string path;
  std::map<std::string, BaselineFinding> findings;  ///< by fingerprint
  PriorSettings settings;  ///< its unit, tolerance and method (check_prior_settings)
};

/// Reads a pdcheck JSON report (`--format json`, any run). The fingerprint is
/// recomputed from the ids (reports older than the field work too). Throws
/// ReportInputError naming the file and the JSON path of a malformed value.
Baseline parse_baseline(const std::string& text, const std::string& path);
Baseline load_baseline(const std::string& path);

/// A current finding against its baseline entry (nullptr: none): new; updated
/// when the status changed or the depth moved materially, i.e. by more than
/// both kBaselineDepthAbs·tolerance and kBaselineDepthRel·(old depth)
/// (src/tolerances.h); else unchanged.
BaselineState compare_finding(const BaselineFinding* old, Status now, double depth,
                              double tolerance);

/// A baseline finding that is no finding now.
struct GoneFinding {
  BaselineFinding was;
  BaselineState state = BaselineState::kUnknown;  ///< kAbsent or kUnknown
  std::string reason;                             ///< why: what was checked, or what was not
};

/// Every baseline finding that the run does not report as a finding: absent
/// when its pair was checked and found clean (separated, or culled by the
/// boxes with both parts loaded), unknown when a part is missing or failed to
/// load, the pair failed, or the pair was not checked (`listed`: the
/// fingerprints the scene's pair list asked for, if it has one). Never
/// "resolved" by absence alone. In the baseline's fingerprint order.
std::vector<GoneFinding> gone_findings(const Baseline& baseline, const RunResult& run,
                                       const std::optional<std::set<std::string>>& listed);

}  // namespace pd
