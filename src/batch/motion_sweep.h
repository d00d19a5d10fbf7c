// Motion sweeps: the signed minimum translational distance of a pair over a
// time grid, each step warm-started from the previous step's direction.
#pragma once

#include "geometry/aabb.h"
#include "results/pair_result.h"
#include "scene/parts.h"
#include "scene/scene.h"
#include "solve/ipopt_local.h"
#include "solve/settings.h"

namespace pd {

struct MotionSweep {
  MotionTrace trace;
  Vec3 direction_at_max = Vec3::UnitZ();
  /// Where: the witness (geometry/depth_witness.h) of the deepest step's
  /// realising piece pair, else of the closest step's.
  std::optional<Vec3> at;
  SolveStats stats;
  std::string fallback;
};

/// Sweeps every piece pair; s(t) is the largest over them (the deepest overlap,
/// else the smallest gap). `warm` = false solves each step from scratch (to
/// measure what the warm start saves).
MotionSweep sweep_pair(const Part& a, const Part& b, const MotionCheck& check,
                       const SolverSettings& s, IpoptLocalSolver& ipopt, bool warm = true);

/// The box a part sweeps over the time grid (its static box when it does not move).
Aabb swept_box(const Part& p, const TimeGrid& grid);

}  // namespace pd
