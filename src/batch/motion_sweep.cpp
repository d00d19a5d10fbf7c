#include "batch/motion_sweep.h"

#include <optional>

#include "batch/piece_pairs.h"
#include "geometry/depth_witness.h"
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
    std::vector<Points> pa(np), pb(nq);
    std::vector<Aabb> ba(np), bb(nq);
    for (size_t i = 0; i < np; ++i) ba[i] = Aabb::of(pa[i] = placed(a, a.pieces[i], t));
    for (size_t j = 0; j < nq; ++j) bb[j] = Aabb::of(pb[j] = placed(b, b.pieces[j], t));
    const PiecePairsResult c = solve_piece_pairs(ba, bb, [&](int i, int j) {
      const SignedSolution r =
          signed_distance(pa[i], pb[j], s, ipopt, warm ? last[i * nq + j] : std::nullopt);
      last[i * nq + j] = r.direction;
      PieceOutcome o =
          make_outcome(i, j, std::max(0.0, r.value), r.direction, std::max(0.0, -r.value));
      o.value = r.value;
      o.stats = r.stats;
      if (!r.fallback.empty()) o.fallback = r.fallback + " at t = " + std::to_string(t);
      return o;
    });
    out.stats += c.stats;
    if (!c.fallback.empty()) out.fallback = c.fallback;
    const double value = c.value;
    const Vec3 dir = c.direction;
    const auto witness = [&] {
      return c.solved ? std::optional<Vec3>(depth_witness(pa[c.piece_a], pb[c.piece_b], dir))
                      : std::nullopt;
    };
    if (check.series) tr.series.emplace_back(t, value);
    if (value > 0 && (!any_overlap || value > tr.max_depth)) {
      any_overlap = true;
      tr.max_depth = value;
      tr.t_max_depth = t;
      out.direction_at_max = dir;
      out.at = witness();
    }
    if (value <= 0 && (!tr.min_distance || -value < *tr.min_distance)) {
      tr.min_distance = -value;
      tr.t_min_distance = t;
      if (!any_overlap) out.direction_at_max = dir, out.at = witness();
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
