// Multi-level single linkage (Rinnooy Kan & Timmer, 1987) over the direction
// of translation, in two variants (docs/solver.md).
#pragma once

#include <random>

#include "solve/ipopt_local.h"
#include "solve/objective.h"
#include "solve/result.h"
#include "solve/settings.h"

namespace pd {

/// pdcheck's MLSL: samples uniform on the unit sphere, geodesic distances (no
/// pole, no wrap-around), the single-linkage start rule, the Bayesian stopping
/// rule over the reduced sample, and fast_local_search. Result in the unit frame.
/// `input`, when given, holds the pair's input coordinates (the points pr was
/// built from): a closed bracket at a small depth is then recomputed exactly
/// from them (solve/exact_facet.h).
struct InputPoints {
  const Points& a;
  const Points& b;
};
DepthSolution mlsl_depth(const PairProblem& pr, IpoptLocalSolver& ipopt, const SolverSettings& s,
                         const InputPoints* input = nullptr);

/// Proves that (v, gap) is the global minimum of the gap (solve/certificate.h),
/// replacing it by a lower facet when one exists; false when the open region is
/// too large to search locally.
bool certify_minimum(const PairProblem& pr, Vec3& v, double& gap, SolveStats& stats);

/// The paper's Algorithm 1 as printed (N, M, σ, τ; the (θ, φ) box; best M
/// samples searched every iteration) with paper_local_search. The baseline.
DepthSolution mlsl_paper_depth(const PairProblem& pr, IpoptLocalSolver& ipopt,
                               const SolverSettings& s);

/// Uniform random numbers and unit vectors from a seeded generator, identical on
/// every platform: mt19937_64's sequence is fixed by the standard, and the
/// conversion to doubles is ours (std:: distributions are not portable).
class SphereSampler {
 public:
  explicit SphereSampler(std::uint64_t seed) : gen_(seed) {}
  double uniform() { return static_cast<double>(gen_() >> 11) * 0x1.0p-53; }  ///< [0, 1)
  /// Archimedes: z uniform in [−1, 1] and a uniform longitude give a uniform point.
  Vec3 direction() {
    const double z = 2.0 * uniform() - 1.0, t = 2.0 * M_PI * uniform();
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(t), r * std::sin(t), z};
  }

 private:
  std::mt19937_64 gen_;
};

}  // namespace pd
