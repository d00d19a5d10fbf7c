// Incremental reruns (--reuse OLD_REPORT.json, docs/scale-out.md): a pair's old
// result stands when both parts' content hashes and the settings hash are the
// ones it was computed under. Read from a report by report/prior_report.h.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "results/pair_result.h"

namespace pd {

struct PriorResults {
  std::string path;
  std::string settings_hash;
  std::map<std::string, std::string> part_hash;  ///< part id -> content hash
  std::map<std::string, PairResult> pairs;       ///< by fingerprint; a, b unset
};

/// The old result of the pair of parts `a` (id, content hash) and `b`, with the
/// current indices, when it can stand: same settings, both parts unchanged, and
/// the pair was solved (an error is always tried again). Marked `reused`.
std::optional<PairResult> prior_result(const PriorResults& prior, const std::string& settings_hash,
                                       int a, const std::string& id_a, const std::string& hash_a,
                                       int b, const std::string& id_b, const std::string& hash_b);

}  // namespace pd
