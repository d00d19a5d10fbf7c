// The one codec of a pair result, in its two encodings (results/field.h): the
// complete one for worker messages and the refinement cache, the report's for
// the report and its readers (merge, --reuse, the HTML page). Both walk the one
// description of the fields (results/pair_fields.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "results/field.h"
#include "results/pair_result.h"
#include "results/part_result.h"

namespace pd {

/// The report's pair entry (docs/report-format.md) of a pair of parts named
/// `id_a` and `id_b`.
nlohmann::ordered_json pair_to_report(const PairResult& r, const std::string& id_a,
                                      const std::string& id_b);
/// A report's pair entry read back, lossless for what pair_to_report writes (JSON
/// numbers are written shortest-round-trip); `a` and `b` are the caller's part
/// indices. Throws std::exception (nlohmann's or invalid_argument) on an entry
/// it cannot read.
PairResult pair_from_report(const nlohmann::ordered_json& j, int a, int b);

/// The report's part entry (docs/report-format.md, `parts`).
nlohmann::ordered_json part_to_report(const PartResult& p);
/// A report's part entry read back, lossless for what part_to_report writes.
/// Throws std::exception on an entry it cannot read.
PartResult part_from_report(const nlohmann::ordered_json& j);

/// The complete encoding: every field, doubles bit for bit (MessagePack keeps
/// NaN, ±Inf and −0, which JSON text would not).
std::string encode_pair_result(const PairResult& r);
/// Throws std::exception on a payload it cannot read, a status outside the enum included.
PairResult decode_pair_result(const std::string& s);

}  // namespace pd
