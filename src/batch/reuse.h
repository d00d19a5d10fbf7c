// Incremental reruns (--reuse OLD_REPORT.json, docs/scale-out.md): a pair's old
// result stands when both parts' content hashes and the settings hash are the
// ones it was computed under. Read from a report by report/prior_report.h.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "results/pair_result.h"

namespace pd {

/// Why a candidate pair's old result does not stand.
enum class ReuseMiss {
  kSettings,     ///< the settings hash differs (solver settings, tolerance or checks)
  kPartChanged,  ///< a part's content hash differs, or the part was not in the report
  kNewPair,      ///< the report has no result for the pair (not a candidate then)
  kError,        ///< its old result is an error: always tried again
  kPairChecks,   ///< its tolerance or clearance (rules, tolerance auto) is another now
};
/// The report's key of a reason (summary.reuse.solved).
const char* reuse_miss_key(ReuseMiss m);

struct PriorResults {
  std::string path;
  std::string settings_hash;
  std::map<std::string, std::string> part_hash;  ///< part id -> content hash
  std::map<std::string, PairResult> pairs;       ///< by fingerprint; a, b unset
};

/// The old result of the pair of parts `a` (id, content hash) and `b`, with the
/// current indices, when it can stand: same settings, both parts unchanged, and
/// the pair was solved (an error is always tried again). Marked `reused`.
/// Pairs of nonconvex parts too: their old result is the refined one, which
/// depends on nothing but the parts and the settings either. Otherwise `why`,
/// when given, gets the reason.
std::optional<PairResult> prior_result(const PriorResults& prior, const std::string& settings_hash,
                                       int a, const std::string& id_a, const std::string& hash_a,
                                       int b, const std::string& id_b, const std::string& hash_b,
                                       ReuseMiss* why = nullptr);

}  // namespace pd
