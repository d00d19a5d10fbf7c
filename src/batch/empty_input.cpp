#include "batch/empty_input.h"

#include <algorithm>

namespace pd {

std::optional<std::string> every_part_failed(const RunResult& run) {
  if (run.parts.empty()) return std::nullopt;
  if (!std::all_of(run.parts.begin(), run.parts.end(), [](const Part& p) { return bool(p.error); }))
    return std::nullopt;
  const std::string n = std::to_string(run.parts.size());
  return "every part failed (" + n + " of " + n +
         ", each named with its error in the report): nothing was checked (--allow-empty accepts "
         "it)";
}

}  // namespace pd
