// The signed minimum translational distance of a pair: the penetration depth
// when the hulls overlap, minus the separation distance when they do not
// (Zhou et al.). Used by clearance checks and motion sweeps only: a static
// interference check never calls it.
#pragma once

#include <optional>

#include "solve/ipopt_local.h"
#include "solve/result.h"
#include "solve/settings.h"

namespace pd {

struct SignedSolution {
  double value = 0.0;              ///< depth (> 0), or −distance (<= 0); world units
  Vec3 direction = Vec3::UnitZ();  ///< moving b by value·direction brings the pair to contact
  SolveStats stats;
  std::string fallback;
};

/// With `warm` (the previous time step's direction) the solve starts there: an
/// Ipopt polish, then the certificate for an overlap, or the separated case's
/// single minimum; without, the configured method from scratch. The separation
/// distance is an Ipopt solve of the 5-variable problem with α free; with
/// method `exact` both come from the Minkowski hull.
SignedSolution signed_distance(const Points& a, const Points& b, const SolverSettings& s,
                               IpoptLocalSolver& ipopt, const std::optional<Vec3>& warm);

}  // namespace pd
