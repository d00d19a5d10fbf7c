#include "solve/mlsl.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

#include "solve/local_search.h"
#include "tolerances.h"

namespace pd {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

struct Optimum {
  Vec3 v;
  double gap;
};

// A descent end point and the optimum its polish reached.
struct Landing {
  Vec3 end;
  size_t optimum;
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

DepthSolution finish(const PairProblem& pr, const std::vector<Optimum>& optima,
                     const Optimum& best_sample, SolveStats stats) {
  DepthSolution s;
  Optimum best = best_sample;
  for (const Optimum& o : optima)
    if (o.gap < best.gap) best = o;
  s.depth = std::max(0.0, best.gap);
  s.direction = best.v;
  stats.distinct_optima = static_cast<int>(optima.size());
  stats.alpha_evaluations += pr.evaluations();
  s.stats = stats;
  return s;
}

}  // namespace

DepthSolution mlsl_depth(const PairProblem& pr, IpoptLocalSolver& ipopt, const SolverSettings& s) {
  const auto t0 = Clock::now();
  SphereSampler rng(s.seed);
  SolveStats stats;
  std::vector<Vec3> x;
  std::vector<double> f;
  std::vector<char> started;
  std::vector<Optimum> optima;
  std::vector<Landing> landings;
  Optimum best_sample{Vec3::UnitZ(), std::numeric_limits<double>::infinity()};
  std::string last_failure;

  for (int k = 1; k <= s.max_iterations; ++k) {
    stats.mlsl_iterations = k;
    for (int i = 0; i < s.samples; ++i) {
      x.push_back(rng.direction());
      f.push_back(pr.gap(x.back()));
      started.push_back(0);
      if (f.back() < best_sample.gap) best_sample = {x.back(), f.back()};
    }
    // A direction with a negative gap is a separating plane: depth 0, certified.
    if (best_sample.gap < 0) return finish(pr, optima, best_sample, stats);

    const long kn = static_cast<long>(x.size());
    // Critical distance on the sphere (area 4π, dimension 2), as an angle.
    const double rk = std::sqrt(4.0 * s.sigma * std::log(double(kn)) / double(kn));
    const double cos_rk =
        std::cos(std::min(rk * s.link_scale, M_PI));  // angle <= r_k  <=>  dot >= cos r_k
    const long reduced = std::max(1L, std::lround(s.reduced * kn));
    std::vector<long> order(kn);
    std::iota(order.begin(), order.end(), 0L);
    std::partial_sort(order.begin(), order.begin() + reduced, order.end(),
                      [&](long a, long b) { return f[a] < f[b] || (f[a] == f[b] && a < b); });

    for (long r = 0; r < reduced; ++r) {
      const long i = order[r];
      if (started[i]) continue;
      // Single linkage: no start next to a better sample or a known optimum.
      bool linked = false;
      for (long j = 0; j < kn && !linked; ++j) linked = f[j] < f[i] && x[i].dot(x[j]) >= cos_rk;
      for (size_t o = 0; o < optima.size() && !linked; ++o)
        linked = x[i].dot(optima[o].v) >= cos_rk;
      if (linked) continue;
      if (stats.local_solves >= s.max_local_solves || seconds_since(t0) > s.max_seconds) break;
      started[i] = 1;
      // The cheap descent first; Ipopt only where it ends somewhere new. An end
      // point next to a known optimum and no lower than it is in its basin.
      const Vec3 end = descend(pr, x[i], stats);
      const double end_gap = pr.gap(end);
      bool known = false;
      for (size_t o = 0; o < optima.size() && !known; ++o)
        known = angle_between(end, optima[o].v) < tol::kSameBasinAngle &&
                end_gap >= optima[o].gap - tol::kTouch;
      for (size_t l = 0; l < landings.size() && !known; ++l)
        known = angle_between(end, landings[l].end) < tol::kSameBasinAngle &&
                end_gap >= optima[landings[l].optimum].gap - tol::kTouch;
      if (known) continue;
      const LocalResult lr = polish(pr, ipopt, end, stats);
      if (lr.gap < best_sample.gap) best_sample = {lr.v, lr.gap};  // a valid bound even unconverged
      if (!lr.converged) {
        last_failure = lr.status;
        continue;
      }
      landings.push_back({end, record(optima, lr)});
      if (lr.gap < 0) return finish(pr, optima, best_sample, stats);
    }
    // Every reduced-sample point is either a start or linked to one, so it counts
    // as a search whose optimum is known (Rinnooy Kan & Timmer, part II, §3).
    const int w = static_cast<int>(optima.size());
    const double wbar = expected_optima(w, reduced);
    if (k >= s.min_iterations && w > 0 && w / wbar >= s.tau) break;
    if (stats.local_solves >= s.max_local_solves || seconds_since(t0) > s.max_seconds) break;
  }
  DepthSolution sol = finish(pr, optima, best_sample, stats);
  if (optima.empty() && best_sample.gap >= 0)
    sol.fallback = "no local solve converged (" + last_failure + ")";
  return sol;
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
        seconds_since(t0) > s.max_seconds)
      break;  // caps far above the paper's typical run: it always stops
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
  DepthSolution sol = finish(pr, optima, best, stats);
  if (optima.empty()) sol.fallback = "no local solve converged (" + last_failure + ")";
  return sol;
}

}  // namespace pd
