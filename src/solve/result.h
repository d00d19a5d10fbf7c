// What a depth solve returns, in the pair's unit frame.
#pragma once

#include <algorithm>
#include <optional>
#include <string>

#include "geometry/types.h"

namespace pd {

/// Why a depth solve stopped (docs/solver.md). Ordered from most to least
/// conclusive: summed stats (pieces, motion steps) keep the least conclusive.
enum class StopReason {
  kNone,             ///< the method has no stop rule (exact, grid, gs-local)
  kProvenSeparated,  ///< a direction with gap <= 0 was found: depth 0, proved
  kContact,          ///< a direction with gap <= kTouch: depth within contact resolution
  kEpaCertificate,   ///< the GJK + EPA bracket closed: its facet is the depth (no sampling)
  kCertificate,      ///< the certificate proved the best direction global (sampling stopped early)
  kBayesian,         ///< the Bayesian rule stopped the sampling (then certified)
  kCap,              ///< a cap on iterations, local solves or time stopped the sampling
  /// The GJK + EPA bracket's lower end is above the tolerance of a pair the
  /// refinement decides on the parts (a nonconvex part): its upper end is the
  /// depth, an upper bound, and no sampling was needed. Appended last: the
  /// worker encoding stores the value.
  kAboveTolerance,
};

/// How little a stop reason proves, for keeping the least conclusive of several
/// solves: the enum's order, with kAboveTolerance (appended) beside the
/// EPA certificate it rests on.
constexpr int stop_rank(StopReason r) {
  return r == StopReason::kAboveTolerance ? 2 * static_cast<int>(StopReason::kEpaCertificate) + 1
                                          : 2 * static_cast<int>(r);
}

/// The report's name of a stop reason ("proven_separated", …).
const char* stop_reason_name(StopReason r);

/// Work counters, reported per pair.
struct SolveStats {
  long alpha_evaluations = 0;
  int local_solves = 0;      ///< local searches started
  int distinct_optima = 0;   ///< distinct local optima found
  int ipopt_iterations = 0;  ///< summed over every Ipopt call
  int ipopt_calls = 0;
  int ipopt_failures = 0;  ///< Ipopt calls that did not converge
  int mlsl_iterations = 0;
  StopReason stop_reason = StopReason::kNone;

  SolveStats& operator+=(const SolveStats& s) {
    if (stop_rank(s.stop_reason) > stop_rank(stop_reason)) stop_reason = s.stop_reason;
    alpha_evaluations += s.alpha_evaluations;
    local_solves += s.local_solves;
    distinct_optima += s.distinct_optima;
    ipopt_iterations += s.ipopt_iterations;
    ipopt_calls += s.ipopt_calls;
    ipopt_failures += s.ipopt_failures;
    mlsl_iterations += s.mlsl_iterations;
    return *this;
  }
};

/// depth >= 0; direction is a unit vector: moving b by depth·direction separates
/// the pair. When depth is 0 the direction is a separating-plane normal pointing
/// from a to b. `distance` is the separation distance when it was computed.
struct DepthSolution {
  double depth = 0.0;
  Vec3 direction = Vec3::UnitZ();
  std::optional<double> distance;
  SolveStats stats;
  std::string fallback;  ///< empty, or what was done instead of the method and why
};

}  // namespace pd
