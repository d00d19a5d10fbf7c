#include "solve/mlsl.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

#include "solve/cap_subdivision.h"
#include "solve/certificate.h"
#include "solve/epa.h"
#include "solve/exact_hull_depth.h"
#include "solve/facet_snap.h"
#include "solve/local_search.h"
#include "solve/neighbourhood.h"
#include "tolerances.h"

namespace pd {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The sample directions depend only on the seed, so every pair a thread solves
// draws the same sequence: it is drawn once per thread and read from then on
// (the draw, a square root and a sine and cosine per sample were a third of
// the time of a contact between 8-vertex boxes). Indexed, not referenced: the
// table grows when a pair needs more iterations than any before it.
class SampleDirections {
 public:
  explicit SampleDirections(std::uint64_t seed) : t_(table()) {
    if (!t_.filled || t_.seed != seed) t_ = {seed, SphereSampler(seed), {}, true};
  }
  const Vec3& operator[](size_t i) {
    while (t_.dirs.size() <= i) t_.dirs.push_back(t_.rng.direction());
    return t_.dirs[i];
  }

 private:
  struct Table {
    std::uint64_t seed = 0;
    SphereSampler rng{0};
    std::vector<Vec3> dirs;
    bool filled = false;
  };
  static Table& table() {
    thread_local Table t;
    return t;
  }
  Table& t_;
};

struct Optimum {
  Vec3 v;
  double gap;
};

// Records a local optimum; returns its index (a new one is appended).
size_t record(std::vector<Optimum>& optima, const LocalResult& r) {
  for (size_t k = 0; k < optima.size(); ++k) {
    if (angle_between(optima[k].v, r.v) < tol::kSameOptimumAngle) {
      if (r.gap < optima[k].gap) optima[k] = {r.v, r.gap};
      return k;
    }
  }
  optima.push_back({r.v, r.gap});
  return optima.size() - 1;
}

// Boender & Rinnooy Kan's Bayesian estimate of the number of local optima after
// `searches` searches found `w` of them; infinite while it is undefined.
double expected_optima(int w, long searches) {
  if (searches <= w + 2) return std::numeric_limits<double>::infinity();
  return w * (searches - 1.0) / (searches - w - 2.0);
}

DepthSolution finish(const PairProblem& pr, const Optimum& best, int distinct, SolveStats stats) {
  DepthSolution s;
  s.depth = best.gap > tol::kGapRounding ? best.gap : 0.0;
  s.direction = best.v;
  stats.distinct_optima = distinct;
  stats.alpha_evaluations += pr.evaluations();
  s.stats = stats;
  return s;
}

// A basin found by the descents: where they end, and a lower bound on the gap
// at its local minimum (the smoothing overestimates the gap by <= μ·log(nm)).
struct Basin {
  Vec3 end;
  double lower;
};

// One basin per distinct descent end point; the lower bound is the smallest seen.
void add_basin(std::vector<Basin>& basins, const Vec3& end, double lower) {
  for (Basin& b : basins) {
    if (angle_between(b.end, end) < tol::kSameBasinAngle) {
      if (lower < b.lower) b = {end, lower};
      return;
    }
  }
  basins.push_back({end, lower});
}

// Ipopt polishes the basins in order of their lower bounds while a bound is
// below the best gap known: a basin whose minimum cannot beat it is skipped.
void polish_basins(const PairProblem& pr, IpoptLocalSolver& ipopt, std::vector<Basin> basins,
                   Optimum& best, SolveStats& stats, std::string& last_failure) {
  std::sort(basins.begin(), basins.end(),
            [](const Basin& a, const Basin& b) { return a.lower < b.lower; });
  bool polished = false;
  for (const Basin& b : basins) {
    if (polished && b.lower >= best.gap - tol::kTouch) break;
    const LocalResult lr = polish(pr, ipopt, b.end, stats);
    if (lr.gap < best.gap) best = {lr.v, lr.gap};  // a valid bound even unconverged
    if (!lr.converged) {
      last_failure = lr.status;
      continue;
    }
    polished = true;
  }
}

// The bracket alone settles the pair when it proves the depth reported:
// - a separating direction (gap <= 0): depth 0;
// - a direction whose gap is within rounding of 0 (GJK's supporting plane
//   through the origin at a contact): the minimum is at or below it, so the
//   depth is 0 by the rule both exact and mlsl follow (kGapRounding);
// - a closed bracket above that rounding: the depth is its upper end, exact to
//   kEpaBracket, contacts (depths up to kTouch) included.
// A closed bracket straddling kGapRounding could be reported either way by the
// exact reference, so MLSL decides it as before.
std::optional<StopReason> bracket_decides(const DepthBracket& b) {
  if (b.separated || b.upper <= 0) return StopReason::kProvenSeparated;
  if (b.upper <= tol::kGapRounding) return StopReason::kContact;
  if (b.certified() && b.lower > tol::kGapRounding) return StopReason::kEpaCertificate;
  return std::nullopt;
}

}  // namespace

bool certify_minimum(const PairProblem& pr, Vec3& v, double& gap, SolveStats& stats) {
  const CellSupports supports = cell_supports(pr, tol::kCertificateGrid);
  stats.alpha_evaluations += static_cast<long>(supports.g.size());
  // A cap's lowest facet depends only on the cap: a later round whose cover
  // repeats a cap (a small improvement rarely moves it) reuses the answer
  // instead of building the same local hull again.
  struct SearchedCap {
    Vec3 centre;
    double radius;
    CapSearch result;
  };
  std::vector<SearchedCap> searched;
  auto search_cap = [&](const Vec3& centre, double radius) {
    for (const SearchedCap& s : searched)
      if (s.centre == centre && s.radius == radius) return s.result;
    const CapSearch c =
        lowest_facet_in_cap(pr.p(), pr.q(), centre, radius, tol::kNeighbourhoodPoints);
    searched.push_back({centre, radius, c});
    return c;
  };
  for (int round = 0; round < 4; ++round) {
    const CapCover cover = open_region_caps(supports, gap, tol::kCertificateGrid,
                                            tol::kCertificateCapAngle, tol::kCertificateCaps);
    if (!cover.ok) return false;
    bool improved = false;
    for (const auto& [centre, radius] : cover.caps) {
      CapSearch c = search_cap(centre, radius);
      if (!c.searched) {
        // Too many differences for one hull (bumpy faces resting on faces): cut
        // the cap into cells bounded like the grid's, down to small exact searches.
        const SubdividedSearch s =
            lowest_facet_subdivided(pr.p(), pr.q(), centre, radius, gap, tol::kNeighbourhoodPoints,
                                    tol::kSubdivisionCells, tol::kTouch);
        stats.alpha_evaluations += s.cells;
        c = s.result;
        // Its lowest cell centre is a real direction too: keep it when it is lower
        // (the next round certifies it or finds the facet below it).
        if (s.result.searched && s.witness_gap < gap &&
            (!c.lowest || s.witness_gap < c.lowest->offset))
          c.lowest = FacetCandidate{s.witness, s.witness_gap};
      }
      if (!c.searched) return false;  // a cap too large to search proves nothing
      if (!c.lowest) continue;
      const double g = pr.gap(c.lowest->normal);
      if (g < gap) {
        v = c.lowest->normal;
        gap = g;
        improved = true;
      }
      // Settled at rounding of 0 (depth 0). A contact above it goes on through
      // the other caps: one may hold a lower facet of the contact.
      if (gap <= tol::kGapRounding) return true;
    }
    if (!improved) return true;
    // The cap's facet is a facet of P − Q, exact to rounding: no Ipopt polish;
    // the next round certifies it with the lower bound.
  }
  return false;
}

namespace {

// The default method's search (mlsl_depth): its samples, the basins found and
// the best direction so far, with one method per phase.
class MlslSearch {
 public:
  MlslSearch(const PairProblem& pr, const SolverSettings& s, const InputPoints* input)
      : pr_(pr),
        s_(s),
        input_(input),
        t0_(Clock::now()),
        directions_(s.seed),
        smoothing_excess_(std::log(double(pr.p().cols())) + std::log(double(pr.q().cols()))) {
    x_.reserve(6 + s.samples);
    f_.reserve(6 + s.samples);
    started_.reserve(6 + s.samples);
  }

  // A direction with gap <= 0 is a separating (or touching) plane: depth 0,
  // proved. Within kTouch of 0 the depth is below the contact resolution, but
  // the depth reported must still be the minimum's: a gap above rounding there
  // (a fitted or local facet of faces flat only to the input's rounding) may
  // have a lower facet elsewhere on the contact, down to a separating one, so
  // the certificate searches for it first (once).
  StopReason settled() {
    if (best_.gap > tol::kGapRounding && best_.gap <= tol::kTouch && !contact_certified_) {
      contact_certified_ = true;
      certify_minimum(pr_, best_.v, best_.gap, stats_);
    }
    if (best_.gap <= 0) return StopReason::kProvenSeparated;
    if (best_.gap <= tol::kTouch) return StopReason::kContact;
    return StopReason::kNone;
  }

  DepthSolution stop(StopReason why) {
    stats_.stop_reason = why;
    return finish(pr_, best_, static_cast<int>(basins_.size()), stats_);
  }

  // GJK + EPA first (solve/epa.h): a closed bracket is the depth, proved, and
  // the solve ends there (the reason returned). An open one (EPA stopped on a
  // face it could not close, or GJK near a contact) hands its best direction
  // to MLSL as the first sample; then the broad phase's overlap axes: gap(±e_k)
  // is the overlap of the pair's boxes along axis k, so the box test's best
  // axis is a sample. On contacts of axis-aligned parts it is the contact normal.
  std::optional<StopReason> seed() {
    const DepthBracket bracket = s_.epa ? epa_bracket(pr_, tol::kEpaMaxIterations) : DepthBracket{};
    if (const auto why = bracket_decides(bracket)) {
      best_ = {bracket.direction, bracket.upper};
      if (*why == StopReason::kEpaCertificate) exact_step(bracket);
      return why;
    }
    if (std::isfinite(bracket.upper)) add_sample(bracket.direction, bracket.upper);
    narrow_open_ = bracket.upper - bracket.lower <= tol::kEpaNarrowBracket;
    for (int k = 0; k < 6; ++k) {
      const Vec3 axis = (k % 2 ? -1.0 : 1.0) * Vec3::Unit(k / 2);
      add_sample(axis, pr_.gap(axis));
    }
    return std::nullopt;
  }

  // Round k: a batch of samples, then local searches from the reduced sample's
  // points not linked to a better one (single linkage). A stop reason when the
  // round settles the pair or stops the loop; kNone to go on.
  StopReason round(int k) {
    stats_.mlsl_iterations = k;
    const size_t first = x_.size();
    for (int i = 0; i < s_.samples; ++i)
      x_.push_back(directions_[size_t(k - 1) * size_t(s_.samples) + size_t(i)]);
    f_.resize(x_.size());
    started_.resize(x_.size(), 0);
    pr_.gaps(x_.data() + first, x_.size() - first, f_.data() + first);
    for (size_t i = first; i < x_.size(); ++i) consider(x_[i], f_[i]);
    if (settled() != StopReason::kNone) return settled();
    const long kn = static_cast<long>(x_.size());
    const long reduced = std::max(1L, std::lround(s_.reduced * kn));
    if (const StopReason why = start_searches(kn, reduced); why != StopReason::kNone) return why;
    // Every reduced-sample point is either a start or linked to one, so it counts
    // as a search whose optimum is known (Rinnooy Kan & Timmer, part II, §3).
    const int w = static_cast<int>(basins_.size());
    if (k >= s_.min_iterations && w > 0 && w / expected_optima(w, reduced) >= s_.tau)
      return StopReason::kBayesian;
    return out_of_budget() ? StopReason::kCap : StopReason::kNone;
  }

  // After the rounds: Ipopt polishes the basins, and the best is certified (or
  // reported as not, for solve_convex_pair's exact fallback).
  DepthSolution polish_and_finish(IpoptLocalSolver& ipopt, StopReason why) {
    std::string last_failure;
    const Optimum before = best_;
    const int distinct = static_cast<int>(basins_.size());
    polish_basins(pr_, ipopt, std::move(basins_), best_, stats_, last_failure);
    if (best_.gap <= tol::kTouch) why = settled();
    const bool certified =
        best_.gap <= tol::kTouch || certify_minimum(pr_, best_.v, best_.gap, stats_);
    stats_.stop_reason = why;
    DepthSolution sol = finish(pr_, best_, distinct, stats_);
    // Too many near-tied minima spread too widely (nearly concentric spheres, say):
    // solve_convex_pair lets the exact hull settle it, and the report says so.
    if (!certified) sol.fallback = "the global minimum could not be certified locally";
    if (!last_failure.empty() && best_.gap == before.gap && best_.gap >= 0)
      sol.fallback = "no local solve converged (" + last_failure + ")";
    return sol;
  }

 private:
  // A closed bracket at a small depth: its facet's distance exactly from the
  // input coordinates, when its near faces prove it (else the bracket stands).
  void exact_step(const DepthBracket& bracket) {
    if (!input_) return;
    const double scale = pr_.frame().scale;
    if (const auto e = exact_bracket_depth(input_->a, input_->b, bracket, scale))
      best_ = {e->direction, e->depth / scale};
  }

  void consider(const Vec3& v, double g) {
    if (g < best_.gap) best_ = {v, g};
  }
  void add_sample(const Vec3& v, double g) {
    x_.push_back(v);
    f_.push_back(g);
    started_.push_back(0);
    consider(v, g);
  }
  bool out_of_budget() const {
    return stats_.local_solves >= s_.max_local_solves || seconds_since(t0_) > s_.max_seconds;
  }

  // Local searches from the `reduced` best of the kn samples, each not within
  // the critical distance of a better sample or a known optimum.
  StopReason start_searches(long kn, long reduced) {
    // Critical distance on the sphere (area 4π, dimension 2), as an angle.
    const double rk = std::sqrt(4.0 * s_.sigma * std::log(double(kn)) / double(kn));
    const double cos_rk =
        std::cos(std::min(rk * s_.link_scale, M_PI));  // angle <= r_k  <=>  dot >= cos r_k
    std::vector<long> order(kn);
    std::iota(order.begin(), order.end(), 0L);
    std::partial_sort(order.begin(), order.begin() + reduced, order.end(),
                      [&](long a, long b) { return f_[a] < f_[b] || (f_[a] == f_[b] && a < b); });
    for (long r = 0; r < reduced; ++r) {
      const long i = order[r];
      if (started_[i]) continue;
      bool linked = false;
      for (long j = 0; j < kn && !linked; ++j) linked = f_[j] < f_[i] && x_[i].dot(x_[j]) >= cos_rk;
      for (size_t o = 0; o < basins_.size() && !linked; ++o)
        linked = x_[i].dot(basins_[o].end) >= cos_rk;
      if (linked) continue;
      if (out_of_budget()) break;
      started_[i] = 1;
      if (const StopReason why = search_from(x_[i]); why != StopReason::kNone) return why;
      if (exact_now_) break;
    }
    return StopReason::kNone;
  }

  // One local search: a descent, the facet it came close to, its basin; then,
  // the first time, the certificate on the best sample's basin (when it holds,
  // no more sampling and no Ipopt call is needed).
  StopReason search_from(const Vec3& start) {
    const DescentOutcome d = descend(pr_, start, stats_);
    consider(d.v, pr_.gap(d.v));
    // The facet the descent came close to, exact, without Ipopt (a contact's).
    if (const auto n = snap_from_descent(pr_.p(), pr_.q(), d.v)) consider(*n, pr_.gap(*n));
    if (settled() != StopReason::kNone) return settled();
    add_basin(basins_, d.v, d.smoothed - d.mu * smoothing_excess_);
    if (tried_certificate_) return StopReason::kNone;
    tried_certificate_ = true;
    const bool certified = certify_minimum(pr_, best_.v, best_.gap, stats_);
    if (settled() != StopReason::kNone) return settled();
    if (!certified && narrow_open_ &&
        double(pr_.p().cols()) * double(pr_.q().cols()) <= tol::kExactHandoverPoints)
      exact_now_ = true;
    return certified ? StopReason::kCertificate : StopReason::kNone;
  }

  const PairProblem& pr_;
  const SolverSettings& s_;
  const InputPoints* input_;
  const Clock::time_point t0_;
  SampleDirections directions_;
  const double smoothing_excess_;
  SolveStats stats_;
  std::vector<Vec3> x_;
  std::vector<double> f_;
  std::vector<char> started_;
  std::vector<Basin> basins_;
  Optimum best_{Vec3::UnitZ(), std::numeric_limits<double>::infinity()};
  bool contact_certified_ = false, tried_certificate_ = false;
  // EPA stopped within kEpaNarrowBracket of closing, and the first certificate
  // found no cover: a band of minima tied to rounding (a shaft on a ring's
  // axis). More searches find a new optimum each and end in the exact hull
  // all the same, so it is taken now (when P − Q is small enough).
  bool narrow_open_ = false, exact_now_ = false;

 public:
  bool exact_now() const { return exact_now_; }
  DepthSolution hand_to_exact() {
    DepthSolution sol = finish(pr_, best_, static_cast<int>(basins_.size()), stats_);
    sol.fallback =
        "EPA's bracket stopped open by rounding and the certificate found the minima tied in a "
        "band";
    return sol;
  }
};

}  // namespace

DepthSolution mlsl_depth(const PairProblem& pr, IpoptLocalSolver& ipopt, const SolverSettings& s,
                         const InputPoints* input) {
  MlslSearch search(pr, s, input);
  if (const auto why = search.seed()) return search.stop(*why);
  if (const StopReason why = search.settled(); why != StopReason::kNone) return search.stop(why);
  StopReason why = StopReason::kCap;  // unless the Bayesian rule stops the loop
  for (int k = 1; k <= s.max_iterations; ++k) {
    const StopReason r = search.round(k);
    if (search.exact_now()) return search.hand_to_exact();
    if (r == StopReason::kNone) continue;
    if (r == StopReason::kBayesian || r == StopReason::kCap) {
      why = r;
      break;
    }
    return search.stop(r);  // settled: separated, contact, certificate
  }
  return search.polish_and_finish(ipopt, why);
}

DepthSolution mlsl_paper_depth(const PairProblem& pr, IpoptLocalSolver& ipopt,
                               const SolverSettings& s) {
  const auto t0 = Clock::now();
  SphereSampler rng(s.seed);
  SolveStats stats;
  std::vector<Optimum> optima;
  Optimum best{Vec3::UnitZ(), std::numeric_limits<double>::infinity()};
  const int n = 2, N = s.paper_n, M = std::min(s.paper_m, s.paper_n);
  const double mu_s = 2.0 * M_PI * M_PI;  // the (θ, φ) box, eq. (5)
  double wbar = std::numeric_limits<double>::infinity();
  std::string last_failure;

  for (int k = 1; double(optima.size()) / wbar < s.tau; ++k) {
    if (k > s.max_iterations * 10 || stats.local_solves >= s.max_local_solves * 10 ||
        seconds_since(t0) > s.max_seconds) {
      stats.stop_reason = StopReason::kCap;
      break;  // caps far above the paper's typical run: it always stops
    }
    stats.mlsl_iterations = k;
    const double kn = double(k) * N;
    const double rk =
        std::pow(std::tgamma(1.0 + n / 2.0) * mu_s * s.sigma * std::log(kn) / kn, 1.0 / n) /
        std::sqrt(M_PI);
    // Step 5: N uniform points of the box, pairwise farther apart than r_k. Early
    // on that is impossible (10 disks of radius r_1/2 exceed the box), so each
    // point takes the best-spread of up to 100 candidates.
    std::vector<std::pair<double, double>> pts;
    while (static_cast<int>(pts.size()) < N) {
      std::pair<double, double> pick{0, 0};
      double pick_sep = -1;
      for (int t = 0; t < 100; ++t) {
        const double th = 2 * M_PI * rng.uniform(), ph = M_PI * rng.uniform() - M_PI / 2;
        double sep = std::numeric_limits<double>::infinity();
        for (auto& [a, b] : pts) sep = std::min(sep, std::hypot(a - th, b - ph));
        if (sep > pick_sep) pick = {th, ph}, pick_sep = sep;
        if (sep > rk) break;
      }
      pts.push_back(pick);
    }
    // Step 6: evaluate, keep the best M.
    std::vector<std::pair<double, int>> val;
    for (int i = 0; i < N; ++i) {
      const Vec3 v = direction_from_angles(pts[i].first, pts[i].second);
      val.emplace_back(pr.alpha(v), i);
    }
    std::sort(val.begin(), val.end());
    for (int m = 0; m < M; ++m) {
      const auto [th, ph] = pts[val[m].second];
      const LocalResult lr = paper_local_search(pr, ipopt, direction_from_angles(th, ph), stats);
      if (lr.gap < best.gap) best = {lr.v, lr.gap};
      if (lr.converged)
        record(optima, lr);  // a new optimum raises w = |X*|
      else
        last_failure = lr.status;
      const int w = static_cast<int>(optima.size());
      if (k * M > w + 2) wbar = expected_optima(w, long(k) * M);
    }
  }
  if (stats.stop_reason == StopReason::kNone) stats.stop_reason = StopReason::kBayesian;
  DepthSolution sol = finish(pr, best, static_cast<int>(optima.size()), stats);
  if (optima.empty()) sol.fallback = "no local solve converged (" + last_failure + ")";
  return sol;
}

}  // namespace pd
