#include "results/fingerprint.h"

#include "hash.h"

namespace pd {

std::string pair_fingerprint(const std::string& id_a, const std::string& id_b) {
  const bool swap = id_b < id_a;
  Hasher h;
  h.add("pdcheck-pair-v1").add(swap ? id_b : id_a).add(swap ? id_a : id_b);
  return h.hex();
}

}  // namespace pd
