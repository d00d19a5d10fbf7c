// The outcome of checking one pair of parts: made by the batch layer, written
// and read back by the report layer. Its fields are described once, in
// results/pair_fields.h, and serialised by one codec (results/codec.h).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "results/exact_check.h"
#include "solve/result.h"

namespace pd {

/// kUndecided: the pair was checked, but its certified depth bracket still
/// straddles the tolerance when the work or time box ran out (exit code 3, as
/// an error: the run could not check everything to the tolerance). Appended
/// last: the worker encoding stores the enum's value.
enum class Status {
  kSeparated,
  kFalsePositive,
  kInterference,
  kError,
  kClearanceViolation,
  kUndecided
};
/// The report's name of a status ("false_positive", ...).
const char* status_name(Status s);
/// The status of a report name (throws std::invalid_argument for an unknown one).
Status status_from_name(const std::string& name);
/// Not decided against the tolerance: an error, or an undecided bracket.
inline bool not_decided(Status s) {
  return s == Status::kError || s == Status::kUndecided;
}

/// A motion sweep's outcome: the signed minimum translational distance s(t)
/// (depth > 0 when overlapping, −distance when not) over the time grid.
struct MotionTrace {
  long steps = 0;
  double max_depth = 0.0, t_max_depth = 0.0;  ///< the deepest step (0 if never overlapping)
  std::optional<double> min_distance;         ///< the smallest separation, if any step is apart
  double t_min_distance = 0.0;
  std::vector<std::pair<double, double>> series;  ///< (t, s(t)), when the scene asks
};

/// Adding a field: declare it here and describe it once in for_each_field
/// (results/pair_fields.h); the worker messages, the refinement cache, the
/// report and its reader (merge, --reuse) all follow (tests/test_codec.cpp).
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
  std::optional<double> clearance_min;  ///< the required clearance, when checked
  /// tolerance auto with a clearance check: the gap artefacts the parts' convex
  /// sags can make where they are closest (docs/numerics.md, "Clearance"): a
  /// distance up to it is a contact, and a clearance is met when distance −
  /// gap_band is; `gap_basis` names the features.
  std::optional<double> gap_band;
  std::string gap_basis;
  std::optional<MotionTrace> motion;  ///< when a part of the pair moves
  std::vector<std::string> warnings;  ///< e.g. a tolerance below the pair's resolution
  // Nonconvex parts (docs/solver.md): what the depth rests on.
  std::optional<std::array<int, 2>> pieces;           ///< the piece pair realising depth/direction
  std::string depth_source = "hull";                  ///< hull, pieces, vertex, mesh-test
  std::optional<double> hull_depth;                   ///< the hull stage's depth, when refined
  std::optional<std::array<double, 2>> depth_bounds;  ///< [lower, upper] when they differ
  std::optional<bool> confirmed;  ///< pairs of a nonconvex part: decided on its own geometry
  std::optional<Vec3> at;  ///< where the depth was found (nonconvex pairs: the thickest overlap)
  std::string reason;      ///< why an undecided pair stayed undecided
  bool reused = false;     ///< taken from an earlier report (--reuse), not solved
  /// The same geometry at the same place (a part placed or exported twice):
  /// an interference that is a mistake of the set-up, said so (Navisworks'
  /// duplicates test).
  bool duplicate = false;
  // tolerance auto (docs/numerics.md): the pair's own band and what it rests on.
  std::optional<double> tolerance;
  std::string tolerance_source;  ///< "measured", "declared" (tolerance auto) or "rule"
  std::string tolerance_basis;   ///< the features, one clause per part
  // Rules (docs/scene-format.md, "Rules"): what covered the pair.
  std::vector<std::string> tests;  ///< the tests that check it, in the rules' order
  std::string expected;            ///< the expected-contact rule covering it, if any
  /// B-rep pairs: the verdict made sure of on the exact solids, or why not.
  std::optional<ExactCheck> exact;
};

/// Status from depth: touching within rounding of the pair size is separated;
/// depth within rounding of the tolerance is a false positive, consistently.
Status classify(double depth, double tolerance, double pair_size);

}  // namespace pd
