#include "batch/refine.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <tuple>

#include "batch/brep_confirm.h"
#include "batch/contact_band.h"
#include "batch/convexity_on_demand.h"
#include "batch/decomposition_cache.h"
#include "batch/locality.h"
#include "batch/pair_queue.h"
#include "batch/pair_workers.h"
#include "batch/part_solids.h"
#include "batch/progress.h"
#include "batch/refine_cache.h"
#include "geometry/decompose.h"
#include "geometry/hull.h"
#include "geometry/mesh_intersect.h"
#include "geometry/solid_distance.h"
#include "geometry/union_find.h"
#include "parallel_for.h"
#include "results/certified_decimal.h"
#include "tolerances.h"
#include "work_queue.h"

namespace pd {

bool needs_refinement(const PairResult& r, const Part& a, const Part& b) {
  return needs_refinement(r, a, a.convex, b, b.convex);
}

bool needs_refinement(const PairResult& r, const Part& a, std::optional<bool> convex_a,
                      const Part& b, std::optional<bool> convex_b) {
  return r.status == Status::kInterference && !r.motion && !r.duplicate &&
         (a.refinable_as(convex_a) || b.refinable_as(convex_b));
}

void note_hull_stage(PairResult& r, const Part& a, const Part& b) {
  // Said of every pair with a part that may be nonconvex, whether or not its
  // convexity was measured (a pair's fields never depend on the other pairs).
  const bool refinable = a.refinable() || b.refinable();
  if (!refinable && !a.convexity_on_demand() && !b.convexity_on_demand()) return;
  if (r.status == Status::kError || needs_refinement(r, a, b)) return;
  // The hulls hold the parts: a verdict short of interference holds for the
  // parts, and so does the depth of convex parts. Motion pairs are swept on
  // hulls, not refined; a duplicate (one mesh placed twice) overlaps wholly.
  r.confirmed = r.status != Status::kInterference || r.duplicate || !refinable;
}

PairResult decide_refined(const PairResult& hull, const MeshVerdict& mesh, const PairResult* pieces,
                          bool complete, double tolerance, double pair_size) {
  PairResult r = hull;
  r.hull_depth = hull.depth;
  r.pieces.reset();
  r.distance.reset();
  if (pieces) {
    r.stats += pieces->stats;
    if (!pieces->fallback.empty()) r.fallback = pieces->fallback;
    if (pieces->status == Status::kError) {
      r.status = Status::kError;
      r.error = "piece pairs: " + pieces->error;
      return r;
    }
  }
  if (!mesh.intersect) {  // the hulls overlap, the parts do not
    r.depth = 0.0;
    r.depth_source = "mesh-test";
    r.confirmed = true;
    r.status = Status::kSeparated;
    r.at.reset();
    if (pieces) {  // a clearance check measured the gap over the pieces
      r.direction = pieces->direction;
      r.pieces = pieces->pieces;
      r.distance = pieces->distance;
      r.gap_band = pieces->gap_band, r.gap_basis = pieces->gap_basis;  // tolerance auto
      if (pieces->status == Status::kClearanceViolation)
        r.status = pieces->status, r.at = pieces->at;
    }
    r.margin = tolerance - r.depth;
    return r;
  }
  const double piece_depth = pieces ? pieces->depth : 0.0;
  const bool by_vertex = mesh.vertex_depth > piece_depth;
  r.depth = std::max(piece_depth, mesh.vertex_depth);
  r.depth_source = by_vertex ? "vertex" : "pieces";
  r.direction = by_vertex || !pieces ? mesh.vertex_direction : pieces->direction;
  if (pieces && !by_vertex) r.pieces = pieces->pieces;
  // Where: the realising vertex's, else the piece pair's witness (else the hull's).
  if (by_vertex && mesh.vertex_at)
    r.at = mesh.vertex_at;
  else if (pieces && pieces->at)
    r.at = pieces->at;
  if (mesh.vertex_depth != hull.depth) r.depth_bounds = {{mesh.vertex_depth, hull.depth}};
  r.status = classify(r.depth, tolerance, pair_size);
  if (pieces && pieces->status == Status::kClearanceViolation && r.status == Status::kSeparated) {
    r.status = pieces->status;
    r.distance = pieces->distance;
    r.gap_band = pieces->gap_band, r.gap_basis = pieces->gap_basis;
    r.at = pieces->at;
  }
  if (r.status == Status::kSeparated) r.at.reset();
  // Pieces from a decomposition that ran out of time are coarse hulls: their depth
  // decides nothing. Only the vertex bound can still confirm an interference;
  // short of it the pair is not quietly passed.
  const bool vertex_decides =
      classify(mesh.vertex_depth, tolerance, pair_size) == Status::kInterference;
  r.confirmed = complete || vertex_decides;
  if (!*r.confirmed) r.status = Status::kInterference;
  r.margin = tolerance - r.depth;
  return r;
}

PairResult decide_thickness(const PairResult& hull, const MeshVerdict& mesh,
                            const ThicknessResult& t, double tolerance, double pair_size,
                            const std::string& why_not) {
  using Outcome = ThicknessResult::Outcome;
  PairResult r = hull;
  r.hull_depth = hull.depth;
  r.pieces.reset();
  r.distance.reset();
  r.depth_source = "thickness";
  r.depth = t.lower;
  r.direction = t.direction;
  r.depth_bounds = {{t.lower, std::min(t.upper, hull.depth)}};
  // Where: the thickest ball's centre, else (no common interior point found)
  // the deepest surface point, where the surfaces cross most.
  if (t.lower > 0)
    r.at = t.at;
  else if (mesh.vertex_at)
    r.at = mesh.vertex_at;
  r.confirmed = true;
  // A part thinner than the tolerance pushed deep into another has a thin
  // overlap: the deepest point of its surface inside the other, a lower bound
  // of any separating move, says it is a clash all the same (when deeper than
  // the coordinates' resolution too: a touching face's rounding is no clash).
  if (classify(mesh.vertex_depth, std::max(tolerance, t.resolution), pair_size) ==
          Status::kInterference &&
      t.outcome != Outcome::kAbove) {
    r.status = Status::kInterference;
    r.depth = mesh.vertex_depth;
    r.depth_source = "surface";
    r.direction = mesh.vertex_direction;
    r.depth_bounds = {{mesh.vertex_depth, hull.depth}};
    r.at = mesh.vertex_at;
  } else if (t.outcome == Outcome::kAbove) {
    r.status = Status::kInterference;
    r.depth = certified_decimal(t.lower, (*r.depth_bounds)[1]);  // the digits it certifies
  } else if (t.outcome == Outcome::kBelow) {
    // Touching to the coordinates' resolution is separated, as for convex
    // pairs; a false positive is an overlap found above it.
    const double upper = (*r.depth_bounds)[1];
    if (upper <= t.resolution || classify(upper, tolerance, pair_size) == Status::kSeparated) {
      r.status = Status::kSeparated;
    } else if (t.lower > t.resolution) {
      r.status = Status::kFalsePositive;
      r.depth = certified_decimal(t.lower, upper);
    } else {  // the work ran out before the bracket left the resolution
      r.status = Status::kFalsePositive;
      r.depth = upper;
      r.reason =
          "the work budget ran out before the bracket came within the coordinates' resolution "
          "or showed an overlap above it: the depth is its upper end";
    }
  } else {
    r.status = Status::kUndecided;
    r.confirmed = false;
    if (t.outcome == Outcome::kNoInside) {
      r.depth = mesh.vertex_depth;
      r.depth_source = "surface";
      r.depth_bounds = {{mesh.vertex_depth, hull.depth}};
      if (mesh.vertex_at) r.at = mesh.vertex_at;
      r.reason = why_not + ": only the surfaces' meeting and the deepest surface point are known";
    } else {
      r.reason = std::string(t.outcome == Outcome::kTime ? "time box" : "work budget") +
                 " reached after " + std::to_string(t.evaluations) +
                 " distance evaluations with the bracket still around the tolerance";
    }
  }
  if (r.status == Status::kSeparated) {  // touching: depth 0, as for convex pairs
    r.depth = 0.0;
    r.at.reset();  // a finding's place only
  }
  r.margin = tolerance - r.depth;
  return r;
}

namespace {

using Clock = std::chrono::steady_clock;

// How far past the first open pair a refinement thread looks for one whose
// parts no other thread is fetching (batch/pair_queue.h): a part's pairs are
// about ten (a ring's balls, its housing and shaft), so a few more keep the
// threads within a part or two of each other.
constexpr size_t kPairLookahead = 16;

// The surfaces' verdict. The thickness path samples the surfaces itself
// (surface_depth, every vertex included), so only the pieces path asks for
// the deepest-vertex bound here.
MeshVerdict mesh_verdict(const PreparedMesh* a, const PreparedMesh* b, bool vertex_bound) {
  MeshVerdict v;
  if (!a || !b) return v;  // no surface to test: may meet, the pieces decide
  v.intersect = meshes_intersect(*a, *b);
  if (v.intersect && vertex_bound) {
    const MeshDepthBound bound = deepest_vertex_depth(*a, *b);
    v.vertex_depth = bound.depth;
    v.vertex_direction = bound.direction;
    // The vertex p and its nearest point q: direction is (p − q) for p of a, (q − p) for p of b.
    if (bound.vertex >= 0)
      v.vertex_at =
          bound.surface_point + (bound.vertex_of_a ? 0.5 : -0.5) * bound.depth * bound.direction;
  }
  return v;
}

// Decomposes each mesh file once (its instances share it) at the strictest
// concavity tolerance of its instances, from the cache when it has it.
void decompose_parts(std::vector<Part>& parts, const std::vector<int>& which,
                     const RunOptions& options) {
  struct FileJob {
    const Part* first = nullptr;
    double tol = 0.0;  ///< file units
    StoredDecomposition result;
    bool cached = false;
  };
  std::map<std::string, FileJob> files;
  for (int k : which) {
    const PartSurface& s = *parts[k].surface;
    FileJob& f = files[s.file_hash];
    const double t = s.concavity_tol / s.stretch;  // the tolerance its convexity was measured at
    if (!f.first || t < f.tol) f.tol = t;
    if (!f.first) f.first = &parts[k];
  }
  std::vector<FileJob*> jobs;
  for (auto& [hash, f] : files) jobs.push_back(&f);
  Progress progress(jobs.size(), options.quiet, "decompositions");
  parallel_for(jobs.size(), options.jobs, [&](size_t k) {
    FileJob& f = *jobs[k];
    const PartSurface& s = *f.first->surface;
    const std::string key = decomposition_key(s.file_hash, f.tol, tol::kDecomposeSeconds);
    if (auto hit = read_cached_decomposition(options.cache_dir, key)) {
      f.result = std::move(*hit);
      f.cached = true;
    } else {
      const auto t0 = Clock::now();
      try {
        const auto d = decompose_convex(*file_mesh_of(s), f.tol, tol::kDecomposeSeconds);
        for (const Points& p : d.pieces) f.result.pieces.push_back(p);
        f.result.complete = d.complete;
        f.result.note = d.note;
      } catch (const std::exception& e) {  // never lose the pair: the hull is a fallback
        f.result.pieces.clear();           // each instance takes its own hull (below)
        f.result.complete = false;
        f.result.note = std::string("decomposition failed: ") + e.what();
      }
      f.result.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
      write_cached_decomposition(options.cache_dir, key, f.result);  // best effort
    }
    progress.tick();
  });
  progress.finish();
  // Each instance hulls its placed pieces (an affine image of a hull is the hull
  // of the image).
  parallel_for(which.size(), options.jobs, [&](size_t n) {
    Part& p = parts[which[n]];
    const FileJob& f = files.at(p.surface->file_hash);
    PartDecomposition d;
    d.seconds = f.result.seconds;
    d.cached = f.cached;
    d.complete = f.result.complete;
    d.note = f.result.note;
    for (const Points& piece : f.result.pieces)
      if (piece.cols() > 0)
        d.pieces.push_back(convex_hull(apply_placement(piece, p.surface->placement)));
    if (d.pieces.empty()) {
      d.pieces = p.pieces;
      d.complete = false;
    }
    p.decomposition = std::move(d);
  });
}

// Step 2 for one pair whose surfaces meet: the overlap thickness, and the
// deepest point of either surface inside the other (into `v`: a lower bound of
// any separating move that needs no inside of the surface's own part); its
// time goes to the pair's, and `why_not` says what an open surface lacks.
// The deepest point is what an open pair reports. Between solids it only
// guards against a thin part pushed deep (decide_thickness), which a thick
// overlap needs no guard against, and only a point deeper than the tolerance
// can decide: it is sought only there, unless the contact's band needs its
// place.
//
// `widen` (bound_widening: B-rep parts with certified sags) narrows a thin
// overlap's bracket until, widened so for the solids, it still lies within
// the tolerance: the bound then certifies the pair and no solid is read.
ThicknessResult measure_thickness(const SolidDistance& a, const SolidDistance& b, double tolerance,
                                  const PairTolerance* band, std::optional<double> widen,
                                  PairResult& r, MeshVerdict& v, std::string& why_not) {
  const auto t0 = Clock::now();
  bool sought = false, whole = false;
  const auto deepest = [&](double only_above) {
    const long budget =
        only_above > -INFINITY ? tol::kSurfaceDepthGuardSamples : tol::kSurfaceDepthSamples;
    const SurfaceDepth ab = surface_depth(a.mesh(), b, budget, only_above);
    const SurfaceDepth ba = surface_depth(b.mesh(), a, budget, only_above);
    v.vertex_depth = std::max(ab.depth, ba.depth);
    v.vertex_direction = ab.depth >= ba.depth ? ab.direction : Vec3(-ba.direction);
    // The middle of the deepest sample p and its nearest point q = p − depth·direction.
    const SurfaceDepth& deeper = ab.depth >= ba.depth ? ab : ba;
    if (deeper.depth > 0) v.vertex_at = deeper.at - 0.5 * deeper.depth * deeper.direction;
    sought = true;
    whole = !(only_above > -INFINITY);
  };
  const bool solids = a.closed() && b.closed();
  if (!solids) deepest(-INFINITY);
  ThicknessResult t = thickness_at_contact(a, b, tolerance, band, r.depth, [&] {
    if (!whole) deepest(-INFINITY);
    return v.vertex_at;
  });
  // B-rep meshes are doubles: the search may narrow below the float32 steps
  // that make a mesh file's contact, down to what the bound needs. Only a
  // bracket within a few times of it, with up to twice the work it took:
  // past that the faces near the contact (the exact stage's local sags) or the
  // solids decide for less.
  const double target = widen ? tolerance - *widen : 0.0;
  if (widen && t.outcome == ThicknessResult::Outcome::kBelow && t.upper + *widen > tolerance &&
      t.lower + *widen <= tolerance && target >= tol::kBoundNarrowing * t.upper) {
    ThicknessLimits limits;
    limits.resolution = target;
    limits.max_evaluations = 2 * std::max(t.evaluations, tol::kThicknessBracketMinEvaluations);
    t = thickness_again(a, b, t, target, tolerance, limits);
  }
  // Only a point deeper than the tolerance and the coordinates' resolution
  // decides; and an overlap certified within the resolution is touching: a
  // part thinner than the resolution is not resolved either.
  if (!sought && t.outcome != ThicknessResult::Outcome::kAbove && !(t.upper <= t.resolution))
    deepest(std::max(tolerance, t.resolution));
  r.time_ms += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  why_not = a.closed() ? b.note() : a.note();
  return t;
}

// The used parts' pieces (their decomposition's, else their own) as
// pieces-only parts, for the worker pool.
std::vector<std::optional<Part>> pieces_only_parts(const std::vector<Part>& parts,
                                                   const std::vector<int>& used) {
  std::vector<std::optional<Part>> out(parts.size());
  for (size_t p = 0; p < parts.size(); ++p) {
    if (!used[p]) continue;
    Part q;
    q.id = parts[p].id;
    q.box = parts[p].box;
    q.pieces = parts[p].decomposition ? parts[p].decomposition->pieces : parts[p].pieces;
    out[p] = std::move(q);
  }
  return out;
}

// The order in which the pairs are refined: by where their parts sit
// (batch/locality.h), so that a part's pairs run close together and its
// distances, built once, serve them from the cache and go after the last.
// - The parts the pairs join are taken group by group (a bearing and its
//   housing), each group at its first part's place: a group across a
//   boundary of the Morton order would otherwise keep its first parts
//   through the groups between its two halves.
// - In a group, each pair is placed by its part with fewer pairs, then by the
//   other: a ball's two pairs (its inner and outer ring) come together, so
//   only a ball or two is held at a time beside the rings, which stay for
//   all of theirs.
std::vector<size_t> by_locality(const std::vector<Part>& parts,
                                const std::vector<std::pair<int, int>>& pairs,
                                const std::vector<size_t>& which) {
  const std::vector<std::uint64_t> code = locality_codes(parts);
  std::vector<int> count(parts.size(), 0);
  UnionFind groups(parts.size());
  for (size_t k : which) {
    const auto [a, b] = pairs[k];
    ++count[size_t(a)], ++count[size_t(b)];
    groups.join(size_t(a), size_t(b));
  }
  std::vector<std::uint64_t> group_at(parts.size(), ~std::uint64_t(0));
  for (size_t p = 0; p < parts.size(); ++p)
    group_at[groups.find(p)] = std::min(group_at[groups.find(p)], code[p]);
  std::vector<size_t> order(which.size());
  for (size_t n = 0; n < order.size(); ++n) order[n] = n;
  const auto key = [&](size_t n) {
    auto [a, b] = pairs[which[n]];
    if (std::make_pair(count[size_t(b)], code[size_t(b)]) <
        std::make_pair(count[size_t(a)], code[size_t(a)]))
      std::swap(a, b);
    const size_t g = groups.find(size_t(a));
    return std::make_tuple(group_at[g], g, code[size_t(a)], code[size_t(b)], which[n]);
  };
  std::sort(order.begin(), order.end(), [&](size_t x, size_t y) { return key(x) < key(y); });
  return order;
}

// The steps of refine_nonconvex_pairs over its pairs, each a method; the
// state one step hands to the next is the members below.
class Refinement {
 public:
  Refinement(std::vector<Part>& parts, const std::vector<std::pair<int, int>>& pairs,
             std::vector<PairResult>& results, const RunOptions& options,
             const std::function<PairChecks(int, int)>& checks, PartSolids& solids,
             ConvexityOnDemand& convexity)
      : parts_(parts),
        pairs_(pairs),
        results_(results),
        options_(options),
        checks_(checks),
        solids_(solids),
        convexity_(convexity) {
    for (size_t k = 0; k < pairs.size(); ++k)
      if (convexity.open(k) ||
          (!results[k].reused &&
           needs_refinement(results[k], parts[pairs[k].first], parts[pairs[k].second])))
        candidates_.push_back(k);
  }

  // 1. Per pair, in an order that keeps a part's pairs together: measure the
  // convexities it turns on (batch/convexity_on_demand.h); when it then needs
  // the refinement, take it from the refinement cache where it was refined
  // before with the same parts, placements and settings (batch/refine_cache.h:
  // none of the steps below runs for it), else test whether the surfaces meet
  // as solids (and how deep the deepest vertex is) and 2. where they meet,
  // measure the overlap thickness. Each part's distances come from a cache
  // bounded by the run's memory budget (RunOptions::memory_mb), built once
  // from its surface in the mesh store, and let go after the part's last pair.
  void settle_and_test() {
    const size_t count = candidates_.size();
    if (count == 0) return;
    std::vector<char> refine(count, 0);
    std::vector<std::optional<StoredRefinement>> hit(count);
    std::vector<std::string> keys(count);
    verdicts_.assign(count, MeshVerdict{});
    thickness_.assign(count, std::nullopt);
    why_not_.assign(count, std::string());
    no_solid_.assign(count, 0);
    std::vector<char> pieces(count, 0);
    const std::vector<size_t> order = by_locality(parts_, pairs_, candidates_);
    // Per part: its pairs not yet done. After its last, its distances go
    // (their memory serves the next part's).
    std::vector<int> left(parts_.size(), 0);
    for (size_t k : candidates_) ++left[size_t(pairs_[k].first)], ++left[size_t(pairs_[k].second)];
    std::mutex left_mutex;
    const auto done = [&](int a, int b) {
      std::vector<int> last;
      {
        std::lock_guard<std::mutex> lock(left_mutex);
        for (int p : {a, b})
          if (--left[size_t(p)] == 0) last.push_back(p);
      }
      for (int p : last) solids_.let_go(p);
    };
    const auto solid_of = [&](int p) -> std::shared_ptr<const SolidDistance> {
      try {  // once per part while it stays in the cache, shared by its pairs and threads
        return solids_.of(p);
      } catch (const std::exception&) {  // no triangles: nothing to test, the pieces decide
        return nullptr;
      }
    };
    Progress progress(count, options_.quiet, "mesh tests");
    std::vector<std::pair<int, int>> parts_in_order;
    for (size_t n : order) parts_in_order.push_back(pairs_[candidates_[n]]);
    PairQueue queue(std::move(parts_in_order), kPairLookahead);
    const auto item = [&](size_t k) {
      const size_t n = order[k];
      const size_t pair = candidates_[n];
      const auto [a, b] = pairs_[pair];
      std::shared_ptr<const SolidDistance> sa, sb;
      try {
        const PairConvexity known = convexity_.settle(pair);
        refine[n] = !results_[pair].reused &&
                    needs_refinement(results_[pair], parts_[a], known.a, parts_[b], known.b);
        if (refine[n] && !options_.cache_dir.empty()) {
          // Keyed by the convexity the pair knows: the same in every run of it.
          keys[n] = refinement_key(parts_[a], known.a, parts_[b], known.b, results_[pair], options_,
                                   checks_(a, b));
          hit[n] = read_cached_refinement(options_.cache_dir, keys[n]);
        }
        if (refine[n] && !hit[n]) sa = solid_of(a), sb = solid_of(b);
      } catch (...) {
        queue.fetched(k);
        done(a, b);
        throw;
      }
      queue.fetched(k);
      try {
        if (refine[n] && !hit[n]) test(n, sa.get(), sb.get(), pieces[n]);
      } catch (...) {
        sa.reset(), sb.reset();
        done(a, b);
        throw;
      }
      sa.reset(), sb.reset();
      done(a, b);
      solids_.give_back_dropped();
      progress.tick();
    };
    // Each thread takes the queue's next pair until none is left; a pair that
    // throws is kept from the others, and the first such rethrown at the end.
    const int threads = std::max(1, std::min<int>(options_.jobs, int(order.size())));
    std::vector<std::exception_ptr> failed(order.size());
    parallel_for(size_t(threads), threads, [&](size_t) {
      while (const std::optional<size_t> k = queue.take()) {
        try {
          item(*k);
        } catch (...) {
          failed[*k] = std::current_exception();
        }
      }
    });
    progress.finish();
    for (const auto& e : failed)
      if (e) std::rethrow_exception(e);
    // The pairs refined here, in the pairs' order, and those the cache held.
    std::vector<MeshVerdict> verdicts;
    std::vector<std::optional<ThicknessResult>> thickness;
    std::vector<std::string> why_not;
    std::vector<char> no_solid;
    for (size_t n = 0; n < count; ++n) {
      if (!refine[n]) continue;
      if (hit[n]) {
        hits_.emplace_back(candidates_[n], std::move(*hit[n]));
        continue;
      }
      if (pieces[n]) solve_.push_back(flagged_.size());
      flagged_.push_back(candidates_[n]);
      if (!options_.cache_dir.empty()) keys_.push_back(std::move(keys[n]));
      verdicts.push_back(verdicts_[n]);
      thickness.push_back(std::move(thickness_[n]));
      why_not.push_back(std::move(why_not_[n]));
      no_solid.push_back(no_solid_[n]);
    }
    verdicts_.swap(verdicts);
    thickness_.swap(thickness);
    why_not_.swap(why_not);
    no_solid_.swap(no_solid);
  }

  // Whether anything is left for the steps below.
  bool empty() const { return flagged_.empty() && hits_.empty() && reused_pieces_.empty(); }

  // Once every convexity is set: the reused refined pairs whose parts' pieces
  // decided. A refined pair taken from an earlier report (--reuse) is final;
  // when its parts' pieces decided it, they are decomposed all the same (from
  // the cache), so the report's part fields are a full run's.
  void note_reused_pieces() {
    for (size_t k = 0; k < pairs_.size(); ++k) {
      const Part &a = parts_[pairs_[k].first], &b = parts_[pairs_[k].second];
      if (results_[k].reused && results_[k].depth_source != "hull" &&
          (a.refinable() || b.refinable()) &&
          (checks_(pairs_[k].first, pairs_[k].second).clearance || a.mode == Pieces::kDecompose ||
           b.mode == Pieces::kDecompose))
        reused_pieces_.push_back(k);
    }
  }

  // 3. Decompose the refinable parts of the pairs that need pieces, and 4.
  // solve their piece pairs in the worker pool (as pieces-only parts).
  void solve_piece_pairs() {
    std::vector<int> used(parts_.size(), 0);
    for (size_t n : solve_) used[pairs_[flagged_[n]].first] = used[pairs_[flagged_[n]].second] = 1;
    for (const auto& [k, hit] : hits_)
      if (hit.solved) used[pairs_[k].first] = used[pairs_[k].second] = 1;
    for (size_t k : reused_pieces_) used[pairs_[k].first] = used[pairs_[k].second] = 1;
    std::vector<int> to_decompose;
    for (size_t p = 0; p < parts_.size(); ++p)
      if (used[p] && parts_[p].refinable() && !parts_[p].decomposition)
        to_decompose.push_back(static_cast<int>(p));
    decompose_parts(parts_, to_decompose, options_);
    const std::vector<std::optional<Part>> piece_parts = pieces_only_parts(parts_, used);
    piece_results_.resize(flagged_.size());
    std::vector<size_t> which(solve_.size());
    for (size_t k = 0; k < which.size(); ++k) which[k] = k;
    auto job = [&](size_t k) {
      const auto [a, b] = pairs_[flagged_[solve_[k]]];
      return PairJob{a, b, &*piece_parts[a], &*piece_parts[b]};
    };
    solve_pairs_in_workers(
        which, job, options_, checks_, "piece pairs",
        [&](size_t k, PairResult r) { piece_results_[solve_[k]] = std::move(r); });
  }

  // 5. Decide each pair (and store it in the cache), then put back the cached ones.
  void decide() {
    bool warned = false;  // a cache that cannot be written is said once
    for (size_t n = 0; n < flagged_.size(); ++n) {
      const auto [a, b] = pairs_[flagged_[n]];
      const Part &pa = parts_[a], &pb = parts_[b];
      const bool complete = (!pa.decomposition || pa.decomposition->complete) &&
                            (!pb.decomposition || pb.decomposition->complete);
      PairResult& r = results_[flagged_[n]];
      r = thickness_[n]
              ? decide_thickness(r, verdicts_[n], *thickness_[n], tolerance_of_pair(flagged_[n]),
                                 pair_size(pa, pb), why_not_[n])
              : decide_refined(r, verdicts_[n], piece_results_[n] ? &*piece_results_[n] : nullptr,
                               complete, tolerance_of_pair(flagged_[n]), pair_size(pa, pb));
      note_pair_tolerance(r, checks_(a, b));
      // Errors (a crashed or timed-out worker) are not stored: a rerun retries.
      if (!keys_.empty() && r.status != Status::kError) {
        const bool solved = std::find(solve_.begin(), solve_.end(), n) != solve_.end();
        const std::string why = write_cached_refinement(options_.cache_dir, keys_[n], {r, solved});
        if (!why.empty() && options_.on_warning && !warned) options_.on_warning(why), warned = true;
      }
      if (options_.on_pair) options_.on_pair(r, parts_);
    }
    for (auto& [k, hit] : hits_) {
      PairResult& r = results_[k];
      hit.result.a = r.a;
      hit.result.b = r.b;
      r = std::move(hit.result);
      note_pair_tolerance(r, checks_(r.a, r.b));
      if (options_.on_pair) options_.on_pair(r, parts_);
    }
  }

 private:
  // Steps 1 and 2 for candidate n, whose parts' distances are sa and sb (null:
  // no surface); `pieces`: its pieces decide (steps 3 and 4).
  void test(size_t n, const SolidDistance* sa, const SolidDistance* sb, char& pieces) {
    const size_t pair = candidates_[n];
    const auto [a, b] = pairs_[pair];
    no_solid_[n] = !sa || !sb;
    const bool by_pieces = needs_pieces(pair, no_solid_[n]);
    try {
      verdicts_[n] =
          mesh_verdict(sa ? &sa->mesh() : nullptr, sb ? &sb->mesh() : nullptr, by_pieces);
    } catch (const std::exception&) {
      verdicts_[n] = MeshVerdict{};  // cannot tell: may meet, pieces decide
    }
    const PairChecks c = checks_(a, b);
    if (by_pieces) {
      pieces = verdicts_[n].intersect || c.clearance;
    } else if (verdicts_[n].intersect || c.clearance) {
      thickness_[n] = measure_thickness(
          *sa, *sb, tolerance_of_pair(pair), c.tolerance ? &*c.tolerance : nullptr,
          bound_widening(parts_[a], parts_[b]), results_[pair], verdicts_[n], why_not_[n]);
    }
  }

  // A clearance check, a part in pieces `decompose` or one without a surface
  // keeps the convex pieces of a whole-part decomposition (steps 3 and 4);
  // every other pair whose surfaces meet gets the overlap thickness (step 2).
  bool needs_pieces(size_t pair, bool no_solid) const {
    const auto [a, b] = pairs_[pair];
    return checks_(a, b).clearance.has_value() || parts_[a].mode == Pieces::kDecompose ||
           parts_[b].mode == Pieces::kDecompose || no_solid;
  }
  double tolerance_of_pair(size_t pair) const {
    const auto [a, b] = pairs_[pair];
    return pair_tolerance_of(checks_(a, b), options_.tolerance);
  }

  std::vector<Part>& parts_;
  const std::vector<std::pair<int, int>>& pairs_;
  std::vector<PairResult>& results_;
  const RunOptions& options_;
  const std::function<PairChecks(int, int)>& checks_;
  PartSolids& solids_;  ///< each part's distances, steps 1–2
  ConvexityOnDemand& convexity_;
  /// Indices into pairs_: the pairs that may need the refinement (their
  /// verdict turns on a convexity, or needs it), step 1; those that need it
  /// and are not in the cache, steps 2–5.
  std::vector<size_t> candidates_, flagged_;
  std::vector<size_t> reused_pieces_;  ///< reused refined pairs whose parts' pieces decided
  std::vector<std::string> keys_;
  std::vector<std::pair<size_t, StoredRefinement>> hits_;
  // Per candidate (index n into candidates_) in step 1, then per flagged pair
  // (index n into flagged_):
  std::vector<MeshVerdict> verdicts_;
  std::vector<char> no_solid_;  ///< a part of the pair has no surface to test
  std::vector<size_t> solve_;   ///< the pairs whose pieces decide
  std::vector<std::optional<ThicknessResult>> thickness_;
  std::vector<std::string> why_not_;
  std::vector<std::optional<PairResult>> piece_results_;
};

}  // namespace

void refine_nonconvex_pairs(std::vector<Part>& parts, const std::vector<std::pair<int, int>>& pairs,
                            std::vector<PairResult>& results, const RunOptions& options,
                            const std::function<PairChecks(int, int)>& checks) {
  PartSolids solids(parts, size_t(std::max(0.0, options.memory_mb)) << 20);
  refine_nonconvex_pairs(parts, pairs, results, options, checks, solids);
}

void refine_nonconvex_pairs(std::vector<Part>& parts, const std::vector<std::pair<int, int>>& pairs,
                            std::vector<PairResult>& results, const RunOptions& options,
                            const std::function<PairChecks(int, int)>& checks, PartSolids& solids) {
  ConvexityOnDemand convexity(parts, pairs, results, checks, options.cache_dir, solids);
  Refinement refinement(parts, pairs, results, options, checks, solids, convexity);
  refinement.settle_and_test();
  convexity.finish(results, options);
  refinement.note_reused_pieces();
  if (refinement.empty()) return;
  refinement.solve_piece_pairs();
  refinement.decide();
}

}  // namespace pd
