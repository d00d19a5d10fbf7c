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
/// and decides it again against the band at its contact (decide_at_contact);
/// then, with a clearance, decide_clearance.
void note_pair_tolerance(PairResult& r, const PairChecks& c);

/// With a clearance (`c.clearance` > 0): a pair closer than it is a
/// `clearance_violation` whatever the reason. A separated pair whose distance
/// (less its gap band under auto) is below the minimum, touching included (the
/// solve says so, it measures the distance); a false positive, an overlap
/// within the tolerance, here. An interference stays one (the more severe
/// finding); undecided and error pairs are left as they are.
void decide_clearance(PairResult& r, const PairChecks& c);

/// Whether a separated pair `distance` apart (`gap_band` of it possibly the
/// tessellation's) is closer than `min`: touching (distance 0, or within the
/// gap band) included.
bool closer_than(double distance, double gap_band, double min);

/// Whether a and b are the same geometry at the same place (a part placed or
/// exported twice): their placed convex pieces coincide vertex for vertex
/// (within tol::kSamePlace of their size plus four coordinate steps) and, when
/// either has a surface of its own (a nonconvex mesh part), both are the same
/// mesh file placed alike.
bool same_placed_geometry(const Part& a, const Part& b);

/// The rounding scale of a pair: input coordinates were rounded at their absolute
/// magnitude, so the box's distance from the origin counts as well as its size
/// (infinite when beyond the double range).
double pair_size(const Part& a, const Part& b);

PairResult solve_part_pair(int ia, const Part& a, int ib, const Part& b, const SolverSettings& s,
                           double tolerance, IpoptLocalSolver& ipopt,
                           const PairChecks& checks = {});

}  // namespace pd
