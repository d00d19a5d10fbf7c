#include "batch/reuse.h"

#include "results/fingerprint.h"

namespace pd {

const char* reuse_miss_key(ReuseMiss m) {
  switch (m) {
    case ReuseMiss::kSettings:
      return "settings";
    case ReuseMiss::kPartChanged:
      return "part_changed";
    case ReuseMiss::kNewPair:
      return "new_pair";
    case ReuseMiss::kError:
      return "error";
    case ReuseMiss::kPairChecks:
      return "pair_checks";
  }
  return "";
}

std::optional<PairResult> prior_result(const PriorResults& prior, const std::string& settings_hash,
                                       int a, const std::string& id_a, const std::string& hash_a,
                                       int b, const std::string& id_b, const std::string& hash_b,
                                       ReuseMiss* why) {
  const auto miss = [&](ReuseMiss m) {
    if (why) *why = m;
    return std::nullopt;
  };
  if (prior.settings_hash != settings_hash) return miss(ReuseMiss::kSettings);
  auto same = [&](const std::string& id, const std::string& hash) {
    const auto it = prior.part_hash.find(id);
    return it != prior.part_hash.end() && it->second == hash;
  };
  if (!same(id_a, hash_a) || !same(id_b, hash_b)) return miss(ReuseMiss::kPartChanged);
  const auto it = prior.pairs.find(pair_fingerprint(id_a, id_b));
  if (it == prior.pairs.end()) return miss(ReuseMiss::kNewPair);
  if (it->second.status == Status::kError) return miss(ReuseMiss::kError);
  PairResult r = it->second;
  r.a = a;
  r.b = b;
  r.reused = true;
  return r;
}

}  // namespace pd
