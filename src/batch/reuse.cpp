#include "batch/reuse.h"

#include "results/fingerprint.h"

namespace pd {

std::optional<PairResult> prior_result(const PriorResults& prior, const std::string& settings_hash,
                                       int a, const std::string& id_a, const std::string& hash_a,
                                       int b, const std::string& id_b, const std::string& hash_b) {
  if (prior.settings_hash != settings_hash) return std::nullopt;
  auto same = [&](const std::string& id, const std::string& hash) {
    const auto it = prior.part_hash.find(id);
    return it != prior.part_hash.end() && it->second == hash;
  };
  if (!same(id_a, hash_a) || !same(id_b, hash_b)) return std::nullopt;
  const auto it = prior.pairs.find(pair_fingerprint(id_a, id_b));
  if (it == prior.pairs.end() || it->second.status == Status::kError) return std::nullopt;
  PairResult r = it->second;
  r.a = a;
  r.b = b;
  r.reused = true;
  return r;
}

}  // namespace pd
