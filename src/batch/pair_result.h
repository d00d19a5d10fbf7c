// The outcome of checking one pair of parts.
#pragma once

#include <optional>
#include <string>

#include "solve/result.h"

namespace pd {

enum class Status { kSeparated, kFalsePositive, kInterference, kError };
const char* status_name(Status s);

struct PairResult {
  int a = -1, b = -1;  ///< part indices
  Status status = Status::kError;
  double depth = 0.0;  ///< scene units
  Vec3 direction = Vec3::UnitZ();
  std::optional<double> distance;
  double margin = 0.0;  ///< tolerance − depth: how far the depth is from flipping the status
  std::string method;
  SolveStats stats;
  double time_ms = 0.0;
  std::string fallback;
  std::string error;
};

/// Status from depth: touching within rounding of the pair size is separated;
/// depth within rounding of the tolerance is a false positive, consistently.
Status classify(double depth, double tolerance, double pair_size);

}  // namespace pd
