// A report's pair entry read back (report_json.h's pair_json, inverted), for
// --reuse and pdcheck merge. Lossless for what pair_json writes: JSON numbers are
// written shortest-round-trip.
#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "batch/pair_result.h"

namespace pd {

/// Status by its report name (throws std::invalid_argument for an unknown one).
Status status_from_name(const std::string& name);

/// The result in a pair entry; `a` and `b` are the given part indices. Throws
/// std::exception (nlohmann's or invalid_argument) on an entry it cannot read.
PairResult pair_from_json(const nlohmann::ordered_json& j, int a, int b);

}  // namespace pd
