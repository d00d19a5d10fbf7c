#include "batch/brep_confirm.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>

#include "batch/pair_tolerance.h"
#include "batch/progress.h"
#include "brep/brep_backend.h"
#include "byte_cache.h"
#include "geometry/convexity.h"
#include "geometry/ray_parity.h"
#include "geometry/same_position.h"
#include "geometry/surface_gap.h"
#include "parallel_for.h"
#include "scene/units.h"
#include "tolerances.h"
#include "work_queue.h"

namespace pd {

std::array<double, 2> mesh_bracket(const PairResult& r, bool convex_pair) {
  if (r.status == Status::kSeparated) return {0.0, 0.0};
  if (r.depth_bounds) return *r.depth_bounds;
  if (r.depth_source == "hull" && !convex_pair) return {0.0, r.depth};
  return {r.depth, r.depth};
}

namespace {

double touch_of(const ExactContext& c) {
  return tol::kExactTouch * c.pair_size;
}

ExactCheck check(ExactVerdict v, ExactBasis b, std::optional<std::array<double, 2>> bounds) {
  ExactCheck e;
  e.verdict = v;
  e.basis = b;
  e.depth_bounds = bounds;
  return e;
}

}  // namespace

std::optional<ExactCheck> certify_by_bound(const PairResult& r, const std::array<double, 2>& mesh,
                                           const ExactContext& c,
                                           std::optional<double> hull_distance) {
  if (!c.bounds || r.status == Status::kError) return std::nullopt;
  const double widen = 2.0 * c.sag;
  if (r.status == Status::kSeparated || r.status == Status::kClearanceViolation) {
    // Apart by more than both sags: the solids are apart too (and, with a
    // clearance, as far as the sags leave of the meshes' distance).
    if (!hull_distance || !(*hull_distance > widen + touch_of(c))) return std::nullopt;
    if (c.clearance && !(*hull_distance - widen >= *c.clearance)) return std::nullopt;
    return check(ExactVerdict::kSeparated, ExactBasis::kBound, std::array{0.0, 0.0});
  }
  const double lo = mesh[0] - widen, hi = mesh[1] + widen;
  const double band = tol::kClassifyBand * c.pair_size;
  if (lo > c.tolerance + band && !c.clearance)
    return check(ExactVerdict::kInterference, ExactBasis::kBound, std::array{lo, hi});
  if (hi <= c.tolerance + band && !c.clearance)
    return check(ExactVerdict::kFalsePositive, ExactBasis::kBound,
                 std::array{std::max(0.0, lo), hi});
  return std::nullopt;
}

std::optional<double> bound_widening(const Part& a, const Part& b) {
  if (!a.brep || !b.brep || a.brep->tessellation.basis != SagBasis::kBound ||
      b.brep->tessellation.basis != SagBasis::kBound)
    return std::nullopt;
  return 2.0 * std::max(a.brep->tessellation.sag, b.brep->tessellation.sag);
}

std::optional<ExactCheck> certify_within_tolerance(const PairResult& r, const ExactContext& c) {
  if (!c.bounds || r.status != Status::kSeparated || c.clearance) return std::nullopt;
  const double hi = (r.depth_bounds ? (*r.depth_bounds)[1] : 0.0) + 2.0 * c.sag;
  if (!(hi <= c.tolerance + tol::kClassifyBand * c.pair_size)) return std::nullopt;
  return check(ExactVerdict::kFalsePositive, ExactBasis::kBound, std::array{0.0, hi});
}

void decide_exact(PairResult& r, const std::array<double, 2>& mesh, const ExactContext& c,
                  const ExactMeasure& m) {
  ExactCheck e;
  e.basis = ExactBasis::kSolids;
  e.seconds = m.seconds;
  if (!m.ok) {
    e.verdict = ExactVerdict::kFailed;
    e.reason = m.error;
    r.exact = e;
    return;
  }
  if (m.distance_exact) e.distance = m.distance;
  const double touch = touch_of(c);
  // The mesh bracket widened by the sags: certified when they are bounds;
  // against estimates the solids are held to twice their width.
  const double widen = 2.0 * c.sag * (c.bounds ? 1.0 : 2.0);
  const double mesh_lo = mesh[0] - widen, mesh_hi = mesh[1] + widen;
  const double band = tol::kClassifyBand * c.pair_size;
  char why[256];
  if (m.distance_timed_out && *m.distance <= touch) {
    std::snprintf(why, sizeof why,
                  "the distance between the solids was not settled within %.3g s (their nearest "
                  "faces' boxes are %.6g apart)",
                  m.seconds, *m.distance);
    e.verdict = ExactVerdict::kTimeout;
    e.reason = why;
    r.exact = e;
    return;
  }
  if (*m.distance > touch) {
    if (mesh_lo > touch) {
      std::snprintf(why, sizeof why,
                    "the solids are %.6g apart; the meshes overlap by at least %.6g beyond the "
                    "sags",
                    *m.distance, mesh_lo);
      e.verdict = ExactVerdict::kInconsistent;
      e.reason = why;
      r.exact = e;
      return;
    }
    e.verdict = ExactVerdict::kSeparated;
    e.depth_bounds = {{0.0, 0.0}};
    if (!m.distance_exact) {
      std::snprintf(why, sizeof why, "apart by at least %.6g (the boxes of their faces)",
                    *m.distance);
      e.reason = why;
    }
  } else {
    // A depth the hulls measured is the move that frees the pair: the solids'
    // overlap thickness bounds it from below only (a ball buried in a block is
    // its diameter thick, its move out is half the block's width and more).
    const bool depth_is_move = r.depth_source == "hull";
    double lo = m.lower, hi = m.upper ? *m.upper : INFINITY;
    if (c.bounds) hi = std::min(hi, mesh[1] + 2.0 * c.sag);  // certified already
    if (lo > mesh_hi + touch || (m.upper && !depth_is_move && *m.upper + touch < mesh_lo)) {
      std::snprintf(why, sizeof why,
                    "the solids' thickness is within [%.6g, %.6g], the meshes' within "
                    "[%.6g, %.6g] with the sags",
                    m.lower, m.upper ? *m.upper : INFINITY, std::max(0.0, mesh_lo), mesh_hi);
      e.verdict = ExactVerdict::kInconsistent;
      e.reason = why;
      r.exact = e;
      return;
    }
    e.depth_bounds = {{lo, hi}};
    if (hi <= touch) {
      e.verdict = ExactVerdict::kTouching;
      e.depth_bounds = {{0.0, 0.0}};
    } else if (lo > c.tolerance + band) {
      e.verdict = ExactVerdict::kInterference;
    } else if (hi <= c.tolerance + band && !depth_is_move) {
      e.verdict = ExactVerdict::kFalsePositive;
    } else if (hi <= c.tolerance + band) {
      e.verdict = ExactVerdict::kFailed;
      std::snprintf(why, sizeof why,
                    "the solids' thickness is within [%.6g, %.6g], within the tolerance, and "
                    "bounds from below only the move that frees them, the pair's depth",
                    lo, hi);
      e.reason = why;
      e.depth_bounds.reset();  // of the thickness, not of the depth
    } else {
      e.verdict = m.common_timed_out ? ExactVerdict::kTimeout : ExactVerdict::kFailed;
      if (!m.common_error.empty()) {
        e.reason = m.common_error;
      } else {
        std::snprintf(why, sizeof why,
                      "the solids' thickness is within [%.6g, %.6g], which holds the tolerance", lo,
                      hi);
        e.reason = why;
      }
      if (!std::isfinite(hi)) e.depth_bounds.reset();
    }
    if (m.volume && decisive(e.verdict)) e.volume = m.volume;
  }
  r.exact = e;
  if (!decisive(e.verdict)) return;
  // The pair agrees with the solids. Where the status changes, so do its numbers.
  const std::array<double, 2> b = *e.depth_bounds;
  const auto set = [&](Status s, double depth) {
    if (r.status == s) return;
    r.status = s;
    r.depth = depth;
    r.depth_source = "exact";
    r.depth_bounds = b;
    r.reason.clear();
  };
  switch (e.verdict) {
    case ExactVerdict::kInterference:
      set(Status::kInterference, b[0]);
      break;
    case ExactVerdict::kFalsePositive:
      set(Status::kFalsePositive, b[1]);
      break;
    default:  // touching or apart: depth 0
      set(Status::kSeparated, 0.0);
      if (e.verdict == ExactVerdict::kSeparated && m.distance_exact) r.distance = m.distance;
      r.at.reset();
      break;
  }
  // A clearance is broken by any approach closer than its minimum.
  if (c.clearance && r.status != Status::kInterference &&
      (e.verdict != ExactVerdict::kSeparated || *m.distance < *c.clearance)) {
    r.status = Status::kClearanceViolation;
    r.distance = e.verdict == ExactVerdict::kSeparated ? *m.distance : 0.0;
  }
  r.confirmed = true;
  r.margin = c.tolerance - r.depth;
}

namespace {

using json = nlohmann::json;

// The worker's answer: the solids' measurements.
json encode(const ExactMeasure& m) {
  json x = {{"ok", m.ok},
            {"error", m.error},
            {"lower", m.lower},
            {"seconds", m.seconds},
            {"timed_out", m.common_timed_out},
            {"common_error", m.common_error}};
  if (m.distance) x["distance"] = *m.distance;
  x["distance_exact"] = m.distance_exact;
  x["distance_timed_out"] = m.distance_timed_out;
  if (m.upper) x["upper"] = *m.upper;
  if (m.volume) x["volume"] = *m.volume;
  return x;
}

ExactMeasure measure_of(const json& x) {
  ExactMeasure m;
  m.ok = x.at("ok").get<bool>();
  m.error = x.at("error").get<std::string>();
  m.lower = x.at("lower").get<double>();
  m.seconds = x.at("seconds").get<double>();
  m.common_timed_out = x.at("timed_out").get<bool>();
  m.common_error = x.at("common_error").get<std::string>();
  if (x.contains("distance")) m.distance = x["distance"].get<double>();
  m.distance_exact = x.at("distance_exact").get<bool>();
  m.distance_timed_out = x.at("distance_timed_out").get<bool>();
  if (x.contains("upper")) m.upper = x["upper"].get<double>();
  if (x.contains("volume")) m.volume = x["volume"].get<double>();
  if (m.ok && !m.distance) m.ok = false, m.error = "no distance measured";
  return m;
}

// The smallest gap between the pieces of two parts' hulls (0 when any overlap).
// A lower bound of the hulls' distance from one direction v: the gap between
// their extents along it (a slab between them), for each piece pair. O(n),
// where the distance solve below costs up to 0.2 s on a finely meshed shaft.
double slab_gap(const Part& a, const Part& b, const Vec3& v) {
  double gap = INFINITY;
  for (const Hull& p : a.pieces)
    for (const Hull& q : b.pieces) {
      const Eigen::RowVectorXd sp = v.transpose() * p.vertices, sq = v.transpose() * q.vertices;
      gap = std::min(gap,
                     std::max({0.0, sq.minCoeff() - sp.maxCoeff(), sp.minCoeff() - sq.maxCoeff()}));
    }
  return gap;
}

// A part's placed surface and its triangle tree, for the meshes' gap.
struct GapSurface {
  std::vector<std::array<Vec3, 3>> triangles;
  TriangleTree tree;
  /// Per triangle, its face's sag (scene units); empty when not known.
  std::vector<double> sags;
  std::vector<int> shell;  ///< per triangle, its shell (for the inside test)
  int shells = 0;
  bool closed = false;  ///< every edge used by an even number of triangles
  Aabb box;             ///< of the corners
  GapSurface(const Mesh& mesh, const Part& p) {
    triangles.resize(size_t(mesh.triangles.cols()));
    for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t)
      for (int k = 0; k < 3; ++k)
        triangles[size_t(t)][size_t(k)] = mesh.vertices.col(mesh.triangles(k, t));
    tree = TriangleTree(triangles);
    if (mesh.vertices.cols() > 0) box = Aabb::of(mesh.vertices);
    const std::vector<std::vector<int>> of_shell = shell_triangles(mesh);
    shells = int(of_shell.size());
    shell.assign(triangles.size(), 0);
    for (size_t s = 0; s < of_shell.size(); ++s)
      for (int t : of_shell[s]) shell[size_t(t)] = int(s);
    closed = mesh.triangles.cols() > 0 && boundary_edges(mesh) == 0;
    if (p.surface && p.surface->stored && p.surface->stored->store && p.brep)
      if (auto s = p.surface->stored->store->get_sags(p.surface->stored->key))
        if (s->size() == triangles.size())
          for (float x : *s) sags.push_back(double(x) * p.brep->stretch);
  }
  size_t bytes() const {  // the corners, and the tree about as much again
    return triangles.size() * (2 * sizeof(triangles[0]) + sizeof(double) + sizeof(int)) +
           (64u << 10);
  }
  /// Whether q may lie inside the solid: strictly inside one of its shells,
  /// or anywhere in its box when the mesh is open (parity means nothing).
  bool may_hold(const Vec3& q) const {
    if ((q.array() < box.lo.array()).any() || (q.array() > box.hi.array()).any()) return false;
    if (!closed) return true;
    std::vector<RaySide> sides(size_t(std::max(shells, 1)));
    ray_parity_sides(tree, shell, box.lo, box.hi, q, sides.data(), sides.size());
    return std::any_of(sides.begin(), sides.end(),
                       [](RaySide s) { return s != RaySide::kOutside; });
  }
};

// The largest face sag of `own`'s triangles within `reach` of `other`'s
// solid — near its surface or inside it — (scene units), or `everywhere` when
// its faces' sags are not known. Only points in or near both solids decide a
// pair's depth, overlap or gap; a face sag away from the other part (a fillet
// away from a seated bore, a pulley's rim away from its hub) cannot move them
// (docs/solver.md, "Where the sag is").
double sag_near(const GapSurface& own, const GapSurface& other, double reach, double everywhere) {
  if (own.sags.empty()) return everywhere;
  double worst = 0.0;
  std::vector<int> near;
  for (size_t t = 0; t < own.triangles.size(); ++t) {
    if (own.sags[t] <= worst) continue;
    const auto& tri = own.triangles[t];
    const Vec3 lo = tri[0].cwiseMin(tri[1]).cwiseMin(tri[2]).array() - reach;
    const Vec3 hi = tri[0].cwiseMax(tri[1]).cwiseMax(tri[2]).array() + reach;
    near.clear();
    other.tree.in_turned_box(Eigen::Matrix3d::Identity(), Vec3::Zero(), lo, hi, near, 0);
    // Farther than `reach` from the other's surface, the triangle lies wholly
    // on one side of it: one corner tells which.
    if (!near.empty() || other.may_hold(tri[0])) worst = own.sags[t];
  }
  return worst;
}

// A lower bound of the distance between two parts' surfaces that do not meet
// and neither holds the other (the mesh test's "separated", or hulls apart),
// sharpened up to `enough`: where the hulls overlap (parts that interlock, a
// hinge's leaves) their gap says nothing, the meshes' does.
double mesh_gap(const GapSurface& a, const GapSurface& b, double enough, double useless) {
  const bool a_smaller = a.triangles.size() <= b.triangles.size();
  const GapSurface& walk = a_smaller ? a : b;  // the smaller walked, the larger's tree asked
  const GapSurface& ask = a_smaller ? b : a;
  return surface_gap_lower_bound(walk.triangles, ask.triangles, ask.tree, enough, useless);
}

}  // namespace

void confirm_brep_pairs(const std::vector<Part>& parts,
                        const std::vector<std::pair<int, int>>& pairs,
                        std::vector<PairResult>& results, const RunOptions& options,
                        const std::function<PairChecks(int, int)>& checks,
                        const std::string& units) {
  std::vector<size_t> held;
  for (size_t k = 0; k < pairs.size(); ++k)
    if (held_for_exact(parts[pairs[k].first], parts[pairs[k].second])) held.push_back(k);
  if (held.empty()) return;
  const double mm = unit_in_mm(units).value_or(1.0);
  std::vector<ExactContext> context(pairs.size());
  std::vector<std::array<double, 2>> mesh(pairs.size());
  std::vector<size_t> to_measure;
  const auto report = [&](size_t k) {
    if (options.on_pair) options.on_pair(results[k], parts);
  };
  for (size_t k : held) {
    const auto [a, b] = pairs[k];
    const Part &pa = parts[a], &pb = parts[b];
    PairResult& r = results[k];
    if (r.status == Status::kError || !pa.brep || !pb.brep) {
      if (r.status != Status::kError) {
        ExactCheck e;
        e.reason = "part \"" + (pa.brep ? pb : pa).id + "\" is a mesh, not a B-rep";
        r.exact = e;
      }
      report(k);
      continue;
    }
    const PairChecks pc = checks(a, b);
    ExactContext& c = context[k];
    c.tolerance = pair_tolerance_of(pc, options.tolerance);
    c.pair_size = pair_size(pa, pb);
    c.sag = std::max(pa.brep->tessellation.sag, pb.brep->tessellation.sag);
    c.bounds = bound_widening(pa, pb).has_value();
    c.clearance = pc.clearance;
    // A convexity left unmeasured (no pair turned on it) is not known convex.
    mesh[k] = mesh_bracket(r, pa.convex.value_or(false) && pb.convex.value_or(false));
    auto e = certify_by_bound(r, mesh[k], c, r.distance);
    // Surfaces that meet (the thickness measured): no gap will show them apart.
    if (!e && r.depth_bounds) e = certify_within_tolerance(r, c);
    if (e) {
      r.exact = *e;
      r.confirmed = true;
      report(k);
      continue;
    }
    to_measure.push_back(k);
  }
  if (to_measure.empty()) return;

  // Pairs with certified sags, before any solid: the sags of the faces in or
  // near the other part only; for pairs apart or touching, the gap between
  // their meshes, else the contact within the tolerance.
  {
    std::vector<size_t> gapped, rest;
    for (size_t k : to_measure) {
      const Status s = results[k].status;
      const bool apart = s == Status::kSeparated || s == Status::kClearanceViolation;
      (context[k].bounds && (apart || results[k].depth_bounds) ? gapped : rest).push_back(k);
    }
    ByteCache<int, GapSurface> surfaces(size_t(std::max(0.0, options.memory_mb)) << 20);
    const auto surface_of = [&](int p) {
      return surfaces.get(p, [&] {
        auto g = std::make_shared<const GapSurface>(placed_mesh_of(*parts[p].surface), parts[p]);
        return ByteCache<int, GapSurface>::Built{g, g->bytes()};
      });
    };
    std::vector<std::optional<ExactCheck>> certified(gapped.size());
    parallel_for(gapped.size(), options.jobs, [&](size_t n) {
      const size_t k = gapped[n];
      const auto [a, b] = pairs[k];
      const PairResult& r = results[k];
      ExactContext& c = context[k];
      const bool apart = r.status == Status::kSeparated || r.status == Status::kClearanceViolation;
      // The hull stage's direction first: its slab often certifies alone.
      double gap = apart ? slab_gap(parts[a], parts[b], r.direction) : 0.0;
      if (apart) certified[n] = certify_by_bound(r, mesh[k], c, gap);
      if (certified[n] || !parts[a].surface || !parts[b].surface) {
        if (!certified[n]) certified[n] = certify_within_tolerance(r, c);
        return;
      }
      std::shared_ptr<const GapSurface> sa, sb;
      try {
        sa = surface_of(a);
        sb = surface_of(b);
      } catch (const std::exception&) {  // no surface to read: the solids decide
        return;
      }
      // Only the sags of faces in or near the other part can move what decides
      // a pair: a deepest point lies in both solids, nearest points of a gap
      // within it and the sags of both (docs/solver.md, "Where the sag is").
      {
        const double hi = r.depth_bounds ? (*r.depth_bounds)[1] : 0.0;
        const double reach =
            2.0 * (hi + 6.0 * c.sag + 1.25 * c.clearance.value_or(0.0)) + touch_of(c);
        c.sag = std::min(
            c.sag, std::max(sag_near(*sa, *sb, reach, c.sag), sag_near(*sb, *sa, reach, c.sag)));
      }
      certified[n] =
          certify_by_bound(r, mesh[k], c, apart ? std::optional<double>(gap) : r.distance);
      if (!certified[n] && apart && (r.depth_source == "mesh-test" || r.depth_source == "hull")) {
        // Surfaces that do not meet, neither inside the other: their own gap
        // (at least the hulls'), sharpened until it certifies (beyond both sags
        // and the clearance, with room for its slack) or cannot.
        const double needed = 2.0 * c.sag + touch_of(c) + c.clearance.value_or(0.0);
        gap = std::max(gap, mesh_gap(*sa, *sb, 1.25 * needed, needed));
        certified[n] = certify_by_bound(r, mesh[k], c, gap);
      }
      if (!certified[n]) certified[n] = certify_within_tolerance(r, c);
    });
    for (size_t n = 0; n < gapped.size(); ++n) {
      const size_t k = gapped[n];
      if (!certified[n]) {
        rest.push_back(k);
        continue;
      }
      results[k].exact = *certified[n];
      results[k].confirmed = true;
      report(k);
    }
    std::sort(rest.begin(), rest.end());
    to_measure.swap(rest);
  }
  if (to_measure.empty()) return;

  Progress progress(to_measure.size(), options.quiet, "exact solids");
  const double seconds = options.pair_timeout > 0
                             ? std::min(options.pair_timeout, tol::kExactSeconds)
                             : tol::kExactSeconds;
  auto task = [&](size_t k) {
    const auto [a, b] = pairs[k];
    const Part &pa = parts[a], &pb = parts[b];
    const PairResult& r = results[k];
    const ExactContext& c = context[k];
    ExactRequest q;
    if (r.at) q.starts.push_back(*r.at);
    const Aabb meet = meeting_region(pa, pb);
    q.starts.push_back(0.5 * (meet.lo + meet.hi));
    q.seconds = seconds;
    q.touch = std::max(touch_of(c), tol::kExactTouchMm / mm);
    q.mm_per_unit = mm;
    q.measure_within = c.clearance.value_or(0.0);
    return encode(measure_exact_pair({pa.brep->file, pa.brep->leaf, pa.brep->placement},
                                     {pb.brep->file, pb.brep->leaf, pb.brep->placement}, q))
        .dump();
  };
  auto done = [&](size_t k, bool ok, const std::string& payload) {
    PairResult& r = results[k];
    const ExactContext& c = context[k];
    try {
      if (!ok) throw std::runtime_error(payload);
      decide_exact(r, mesh[k], c, measure_of(json::parse(payload)));
    } catch (const std::exception& e) {
      ExactCheck x;
      const bool late = !ok && payload.rfind("timed out", 0) == 0;
      x.verdict = late ? ExactVerdict::kTimeout : ExactVerdict::kFailed;
      x.reason = late ? "the exact check passed the pair timeout" : e.what();
      r.exact = x;
    }
    report(k);
    progress.tick();
  };
  QueueOptions queue{options.jobs, options.pair_timeout > 0 ? options.pair_timeout + 5.0 : 0.0,
                     options.on_warning};
  if (!to_measure.empty()) preload_brep_backend();  // once, before the workers are forked
  run_work_queue(to_measure, queue, task, done);
  progress.finish();
}

}  // namespace pd
