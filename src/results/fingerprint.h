// The stable identity of a pair of parts across runs (baselines, suppressions,
// shards, permalinks): docs/report-format.md, "fingerprint".
#pragma once

#include <string>

namespace pd {

/// 32 hex digits from the two part ids alone: the same whatever the load order,
/// the A/B order, the run or the machine. Ids are compared bytewise and the
/// smaller one hashed first ("pdcheck-pair-v1", lo, hi, each length-prefixed).
std::string pair_fingerprint(const std::string& id_a, const std::string& id_b);

}  // namespace pd
