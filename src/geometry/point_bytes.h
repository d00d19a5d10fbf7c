// Point sets as bytes, for the cache entries that store them (decompositions,
// file hulls): lossless and compact, each set its count, then its 3·count
// doubles as stored in memory.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/types.h"

namespace pd {

std::string point_sets_bytes(const std::vector<Points>& sets);

/// `count` sets from `bytes` at `offset`, which must end exactly at the end of
/// `bytes`; nullopt when it does not (a short, long or garbled entry).
std::optional<std::vector<Points>> point_sets_from_bytes(const std::string& bytes, size_t offset,
                                                         long count);

}  // namespace pd
