#include "batch/motion_sweep.h"

#include <optional>

#include "solve/signed_distance.h"

namespace pd {

namespace {

Points placed(const Part& p, const Hull& h, double t) {
  return p.motion ? p.motion->at(h.vertices, t) : h.vertices;
}

}  // namespace

MotionSweep sweep_pair(const Part& a, const Part& b, const MotionCheck& check,
                       const SolverSettings& s, IpoptLocalSolver& ipopt, bool warm) {
  MotionSweep out;
  MotionTrace& tr = out.trace;
  const size_t np = a.pieces.size(), nq = b.pieces.size();
  std::vector<std::optional<Vec3>> last(np * nq);
  tr.steps = check.grid.steps();
  bool any_overlap = false;
  for (long k = 0; k < tr.steps; ++k) {
    const double t = check.grid.time(k);
    double value = -std::numeric_limits<double>::infinity();
    Vec3 dir = Vec3::UnitZ();
    for (size_t i = 0; i < np; ++i) {
      for (size_t j = 0; j < nq; ++j) {
        const SignedSolution r =
            signed_distance(placed(a, a.pieces[i], t), placed(b, b.pieces[j], t), s, ipopt,
                            warm ? last[i * nq + j] : std::nullopt);
        last[i * nq + j] = r.direction;
        out.stats += r.stats;
        if (!r.fallback.empty()) out.fallback = r.fallback + " at t = " + std::to_string(t);
        if (r.value > value) value = r.value, dir = r.direction;
      }
    }
    if (check.series) tr.series.emplace_back(t, value);
    if (value > 0 && (!any_overlap || value > tr.max_depth)) {
      any_overlap = true;
      tr.max_depth = value;
      tr.t_max_depth = t;
      out.direction_at_max = dir;
    }
    if (value <= 0 && (!tr.min_distance || -value < *tr.min_distance)) {
      tr.min_distance = -value;
      tr.t_min_distance = t;
      if (!any_overlap) out.direction_at_max = dir;
    }
  }
  return out;
}

Aabb swept_box(const Part& p, const TimeGrid& grid) {
  Aabb box = p.box;
  if (!p.motion) return box;
  for (long k = 0; k < grid.steps(); ++k)
    for (const Hull& h : p.pieces)
      box = box.merged(Aabb::of(p.motion->at(h.vertices, grid.time(k))));
  return box;
}

}  // namespace pd
