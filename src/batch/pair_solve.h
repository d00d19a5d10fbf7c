// Solving one pair of parts: every piece pair, the deepest one counts.
#pragma once

#include "batch/pair_tolerance.h"
#include "results/pair_result.h"
#include "scene/parts.h"
#include "scene/scene.h"
#include "solve/ipopt_local.h"
#include "solve/settings.h"

namespace pd {

/// What a pair is checked for beyond the static depth; empty for a static scene.
struct PairChecks {
  std::optional<double> clearance;         ///< the required clearance
  const MotionCheck* motion = nullptr;     ///< set when a part of the pair moves
  std::optional<PairTolerance> tolerance;  ///< tolerance auto: the pair's own band
  std::string units = "mm";                ///< the scene's, for lengths in messages
};

/// The tolerance the pair is decided against: its own band under auto, else `scene`.
inline double pair_tolerance_of(const PairChecks& c, double scene) {
  return c.tolerance ? c.tolerance->value : scene;
}

/// Records in `r` the band it was decided against, under auto (report fields),
/// and decides it again against the band at its contact (decide_at_contact).
void note_pair_tolerance(PairResult& r, const PairChecks& c);

/// The rounding scale of a pair: input coordinates were rounded at their absolute
/// magnitude, so the box's distance from the origin counts as well as its size
/// (infinite when beyond the double range).
double pair_size(const Part& a, const Part& b);

PairResult solve_part_pair(int ia, const Part& a, int ib, const Part& b, const SolverSettings& s,
                           double tolerance, IpoptLocalSolver& ipopt,
                           const PairChecks& checks = {});

}  // namespace pd
