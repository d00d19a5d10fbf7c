#include "batch/pair_solve.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "batch/contact_band.h"
#include "batch/motion_sweep.h"
#include "batch/piece_pairs.h"
#include "geometry/depth_witness.h"
#include "scene/part_convexity.h"
#include "scene/setup_warnings.h"
#include "solve/epa.h"
#include "solve/methods.h"
#include "solve/objective.h"
#include "solve/signed_distance.h"
#include "tolerances.h"

namespace pd {

namespace {

std::vector<Aabb> piece_boxes(const Part& p) {
  std::vector<Aabb> boxes;
  for (const Hull& h : p.pieces) boxes.push_back(Aabb::of(h.vertices));
  return boxes;
}

// Where a pair's depth (or gap) is: the witness of its realising piece pair
// along that pair's direction (geometry/depth_witness.h).
struct WitnessInputs {
  int piece_a = -1, piece_b = -1;
  Vec3 direction = Vec3::UnitZ();
  std::optional<Vec3> at(const Part& a, const Part& b) const {
    if (piece_a < 0 || piece_b < 0) return std::nullopt;
    return depth_witness(a.pieces[piece_a].vertices, b.pieces[piece_b].vertices, direction);
  }
};

// The static check: the deepest piece pair counts (combine_piece_outcomes).
// A piece pair whose GJK + EPA bracket is above `above` (world units) needs
// nothing more of the hull stage when the refinement decides the pair on the
// parts anyway: the bracket's upper end is its depth, an upper bound, as the
// refinement uses the hull depth. nullopt: the bracket does not get that far.
std::optional<DepthSolution> above_tolerance(const Points& a, const Points& b, double above) {
  const PairProblem pr(a, b);
  const DepthBracket br = epa_bracket(pr, tol::kEpaMaxIterations);
  const double lower = pr.frame().length_to_world(br.lower);
  const double upper = pr.frame().length_to_world(br.upper);
  if (br.separated || !std::isfinite(upper) || !(lower > above)) return std::nullopt;
  DepthSolution d;
  d.depth = upper;
  d.direction = br.direction;
  d.stats.alpha_evaluations = pr.evaluations();
  d.stats.stop_reason = StopReason::kAboveTolerance;
  return d;
}

// `refined_above`: the tolerance of a pair the refinement decides when its hull
// depth exceeds it (above_tolerance).
WitnessInputs solve_static(const Part& a, const Part& b, const SolverSettings& s,
                           IpoptLocalSolver& ipopt, PairResult& r,
                           std::optional<double> refined_above = std::nullopt) {
  const PiecePairsResult c = solve_piece_pairs(piece_boxes(a), piece_boxes(b), [&](int i, int j) {
    std::optional<DepthSolution> early;
    if (refined_above && s.method == Method::kMlsl)
      early = above_tolerance(a.pieces[i].vertices, b.pieces[j].vertices, *refined_above);
    const DepthSolution d =
        early ? *early : solve_convex_pair(a.pieces[i].vertices, b.pieces[j].vertices, s, ipopt);
    PieceOutcome o = make_outcome(i, j, d.depth, d.direction, d.distance);
    o.stats = d.stats;
    o.fallback = d.fallback;
    return o;
  });
  r.stats += c.stats;
  if (!c.fallback.empty()) r.fallback = c.fallback;
  r.depth = c.depth;
  r.direction = c.direction;
  r.distance = c.distance;
  if (a.pieces.size() * b.pieces.size() > 1) r.pieces = {c.piece_a, c.piece_b};
  return {c.solved ? c.piece_a : -1, c.solved ? c.piece_b : -1, c.direction};
}

// The separation distance of a separated pair: the smallest over its piece
// pairs, each warm-started from the static solve's separating direction.
WitnessInputs static_distance(const Part& a, const Part& b, const SolverSettings& s,
                              IpoptLocalSolver& ipopt, PairResult& r) {
  const Vec3 warm = r.direction;
  const PiecePairsResult c = solve_piece_pairs(piece_boxes(a), piece_boxes(b), [&](int i, int j) {
    const SignedSolution d =
        signed_distance(a.pieces[i].vertices, b.pieces[j].vertices, s, ipopt, warm);
    PieceOutcome o =
        make_outcome(i, j, std::max(0.0, d.value), d.direction, std::max(0.0, -d.value));
    o.stats = d.stats;
    return o;
  });
  r.stats += c.stats;
  r.distance = c.distance;
  // One piece pair: the static direction already separates it (kept, so a convex
  // pair reports as before); several: the closest piece pair's direction.
  if (a.pieces.size() * b.pieces.size() > 1) {
    r.direction = c.direction;
    r.pieces = {c.piece_a, c.piece_b};
  }
  // The closest piece pair's own direction: the static one (kept above for a
  // single piece pair) separates, but need not be where the gap is smallest.
  return {c.solved ? c.piece_a : -1, c.solved ? c.piece_b : -1, c.direction};
}

// The largest coordinate plus the box diagonal, without overflow in the
// diagonal's squares (for boxes beyond ~1e154); infinite only when the sum
// itself is beyond the double range.
double rounding_scale(const Aabb& box) {
  double diag = (box.hi - box.lo).norm();
  if (!std::isfinite(diag)) diag = 2 * (0.5 * box.hi - 0.5 * box.lo).stableNorm();
  return box.hi.cwiseAbs().cwiseMax(box.lo.cwiseAbs()).maxCoeff() + diag;
}

// Depths up to kTouch of the pair's rounding scale cannot be told from contact
// (a 1-unit part against one 1e30 units large): when the tolerance is below
// that, a shallow interference reads as separated or a false positive, and the
// report must say the depth was not resolvable.
std::optional<std::string> unresolved_tolerance(double tolerance, double size, Status status,
                                                const std::string& units) {
  const double resolution = tol::kTouch * size;
  if (!(tolerance < resolution) || status == Status::kInterference) return std::nullopt;
  std::ostringstream w;
  w << std::setprecision(3) << "depth below the resolvable scale: the pair's coordinates span "
    << size << " " << units << ", so depths up to " << resolution << " " << units
    << " (1e-11 of that) cannot be told from contact, and the tolerance " << tolerance << " "
    << units << " is smaller: an interference this shallow is not seen";
  return w.str();
}

// The first number of a result that is not finite, or nullptr: such a result
// comes from arithmetic that overflowed and must not pass as a finding.
const char* non_finite_field(const PairResult& r) {
  if (!std::isfinite(r.depth)) return "depth";
  if (!r.direction.allFinite()) return "direction";
  if (!std::isfinite(r.margin)) return "margin";
  if (r.distance && !std::isfinite(*r.distance)) return "distance";
  if (r.at && !r.at->allFinite()) return "witness point";
  if (r.motion) {
    const MotionTrace& m = *r.motion;
    if (!std::isfinite(m.max_depth) || !std::isfinite(m.t_max_depth) ||
        !std::isfinite(m.t_min_distance) || (m.min_distance && !std::isfinite(*m.min_distance)))
      return "motion trace";
    for (const auto& [t, s] : m.series)
      if (!std::isfinite(t) || !std::isfinite(s)) return "motion series";
  }
  return nullptr;
}

// The columns of p in lexicographic order.
std::vector<Vec3> sorted_points(const Points& p) {
  std::vector<Vec3> v(static_cast<size_t>(p.cols()));
  for (Eigen::Index k = 0; k < p.cols(); ++k) v[k] = p.col(k);
  std::sort(v.begin(), v.end(), [](const Vec3& x, const Vec3& y) {
    return std::lexicographical_compare(x.data(), x.data() + 3, y.data(), y.data() + 3);
  });
  return v;
}

// Lexicographic order puts two copies of a point set in the same order only
// when no coordinate differs by rounding across a tie: matched greedily
// instead, each point against its nearest unmatched one within `eps`.
bool same_points(const Points& p, const Points& q, double eps) {
  if (p.cols() != q.cols()) return false;
  const std::vector<Vec3> a = sorted_points(p), b = sorted_points(q);
  std::vector<bool> used(b.size(), false);
  for (const Vec3& x : a) {
    // Candidates: those whose first coordinate is within eps (b is sorted by it).
    auto it = std::lower_bound(b.begin(), b.end(), x.x() - eps,
                               [](const Vec3& y, double v) { return y.x() < v; });
    bool found = false;
    for (; it != b.end() && it->x() <= x.x() + eps && !found; ++it) {
      const size_t k = static_cast<size_t>(it - b.begin());
      if (!used[k] && (*it - x).cwiseAbs().maxCoeff() <= eps) used[k] = found = true;
    }
    if (!found) return false;
  }
  return true;
}

}  // namespace

bool same_placed_geometry(const Part& a, const Part& b) {
  if (a.error || b.error || a.pieces.size() != b.pieces.size() || a.pieces.empty()) return false;
  const double size = std::max((a.box.hi - a.box.lo).norm(), (b.box.hi - b.box.lo).norm());
  const double eps =
      tol::kSamePlace * size + 4 * std::max(a.resolution.value_or(0.0), b.resolution.value_or(0.0));
  if ((a.box.lo - b.box.lo).cwiseAbs().maxCoeff() > eps ||
      (a.box.hi - b.box.hi).cwiseAbs().maxCoeff() > eps)
    return false;
  // A surface of its own (a nonconvex part): the hull is not the part, the
  // same file placed alike is.
  if (a.surface || b.surface) {
    if (!a.surface || !b.surface || a.surface->file_hash != b.surface->file_hash) return false;
    const Mat4& pa = a.surface->placement;
    const Mat4& pb = b.surface->placement;
    if ((pa.topLeftCorner<3, 3>() - pb.topLeftCorner<3, 3>()).cwiseAbs().maxCoeff() >
            tol::kSamePlace ||
        (pa.topRightCorner<3, 1>() - pb.topRightCorner<3, 1>()).cwiseAbs().maxCoeff() > eps)
      return false;
  }
  for (size_t k = 0; k < a.pieces.size(); ++k)
    if (!same_points(a.pieces[k].vertices, b.pieces[k].vertices, eps)) return false;
  return true;
}

double pair_size(const Part& a, const Part& b) {
  return rounding_scale(a.box.merged(b.box));
}

void note_pair_tolerance(PairResult& r, const PairChecks& c) {
  if (c.tolerance) {
    r.tolerance = c.tolerance->value;
    r.tolerance_source = c.tolerance->source;
    r.tolerance_basis = c.tolerance->basis;
    decide_at_contact(r, *c.tolerance);
  }
  decide_clearance(r, c);
}

bool closer_than(double distance, double gap_band, double min) {
  return std::max(0.0, distance - gap_band) < min;
}

void decide_clearance(PairResult& r, const PairChecks& c) {
  if (!c.clearance || !(*c.clearance > 0)) return;
  if (r.status == Status::kFalsePositive) r.status = Status::kClearanceViolation;
}

PairResult solve_part_pair(int ia, const Part& a, int ib, const Part& b, const SolverSettings& s,
                           double scene_tolerance, IpoptLocalSolver& ipopt,
                           const PairChecks& checks) {
  const double tolerance = pair_tolerance_of(checks, scene_tolerance);
  const auto t0 = std::chrono::steady_clock::now();
  PairResult r;
  r.a = ia;
  r.b = ib;
  r.method = method_name(s.method);
  if (a.error || b.error) {
    r.status = Status::kError;
    r.error = "part \"" + (a.error ? a.id : b.id) +
              "\" could not be loaded: " + (a.error ? *a.error : *b.error);
    return r;
  }
  try {
    r.clearance_min = checks.clearance;
    WitnessInputs witness;
    if (checks.motion) {  // the sweep replaces the static solve
      const MotionSweep sw = sweep_pair(a, b, *checks.motion, s, ipopt);
      r.motion = sw.trace;
      r.depth = sw.trace.max_depth;
      r.direction = sw.direction_at_max;
      r.distance = sw.trace.min_distance;
      r.fallback = sw.fallback;
      r.stats += sw.stats;
      r.at = sw.at;  // the deepest step's (else the closest step's)
    } else {
      // A pair with a nonconvex part is decided on the parts once its hulls
      // overlap by more than the tolerance (batch/refine.h): the hull stage
      // need not pin its depth down past that.
      // A part whose convexity is not measured yet may be nonconvex: the
      // measurement after this stage solves the pair again if both are convex.
      const bool refined =
          (a.refinable() || b.refinable() || convexity_unmeasured(a) || convexity_unmeasured(b)) &&
          !checks.clearance;
      witness = solve_static(a, b, s, ipopt, r,
                             refined ? std::optional<double>(tolerance) : std::nullopt);
    }
    // Rounding scale of the pair: input coordinates were rounded at their absolute
    // magnitude, so the box's distance from the origin counts as well as its size.
    const double size = pair_size(a, b);
    if (!std::isfinite(size))
      throw std::runtime_error(
          "the pair's coordinates are too large for double-precision arithmetic (its box "
          "reaches beyond 1e307)");
    r.status = classify(r.depth, tolerance, size);
    r.margin = tolerance - r.depth;
    if (const auto w = unresolved_tolerance(tolerance, size, r.status, checks.units))
      r.warnings.push_back(*w);
    if (r.status != Status::kSeparated && !checks.motion) r.distance.reset();
    if (checks.clearance && r.status == Status::kSeparated) {
      if (!checks.motion) witness = static_distance(a, b, s, ipopt, r);
      // Touching within rounding is distance 0, as an overlap that small is depth 0.
      if (r.distance && *r.distance <= tol::kTouch * size) r.distance = 0.0;
      // Under auto, the gap band of the convex sags where the gap is: the part
      // of the distance the tessellation can have made. Closer than the
      // minimum, touching included, is a violation (decide_clearance).
      note_gap_band(r, checks.tolerance ? &*checks.tolerance : nullptr,
                    checks.motion ? r.at : witness.at(a, b));
      if (r.distance && closer_than(*r.distance, r.gap_band.value_or(0.0), *checks.clearance))
        r.status = Status::kClearanceViolation;
    }
    // A part placed twice: said as such (a moving one is not in one place).
    r.duplicate = !checks.motion && r.status != Status::kSeparated && same_placed_geometry(a, b);
    if (r.duplicate)  // a set-up mistake: on stderr with the others (report/warning_lines.h)
      r.warnings.push_back(std::string(kPlacedTwice) +
                           ": the same geometry at the same place: remove one of them");
    // Every finding says where it is; a clean pair needs no place.
    if (r.status == Status::kSeparated)
      r.at.reset();
    else if (!checks.motion)
      r.at = witness.at(a, b);
    if (const char* bad = non_finite_field(r)) {
      r.status = Status::kError;
      r.error = std::string("the solve gave a non-finite ") + bad +
                ": the coordinates are too large for double-precision arithmetic";
    }
  } catch (const std::exception& e) {
    r.status = Status::kError;
    r.error = e.what();
  }
  r.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace pd
