// Depth methods and their settings (CLI --method, the scene's "solver" block).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace pd {

enum class Method { kMlsl, kMlslPaper, kGsLocal, kGrid, kExact };

std::optional<Method> parse_method(const std::string& name);
std::string method_name(Method m);

struct SolverSettings {
  Method method = Method::kMlsl;
  std::uint64_t seed = 1;  ///< same input + same seed = same depths, bit for bit

  // mlsl: multi-level single linkage on the unit sphere (docs/solver.md).
  int samples = 400;      ///< N, uniform samples per iteration
  double reduced = 0.05;  ///< γ, fraction of all samples kept as the reduced sample
  double sigma = 4.01;    ///< σ > 4 in the critical distance r_k
  double tau = 0.9;       ///< stop when the expected fraction of optima found reaches τ
  int min_iterations = 2;
  double link_scale =
      0.3;  ///< multiplies r_k in the start rule (1 = Rinnooy Kan & Timmer; docs/solver.md)
  int max_iterations = 50;  ///< hard caps: MLSL always stops
  int max_local_solves = 60;
  double max_seconds = 30.0;

  // mlsl-paper: the paper's Algorithm 1 with its parameters.
  int paper_n = 10;
  int paper_m = 3;

  int grid = 40;     ///< grid: GS-k, 2k(k+1) directions, k per π in each angle
  int gs_local = 3;  ///< gs-local: a k×k grid of Ipopt starts (the paper's GS-SQP)
};

/// Largest k a scene may give: GS-1000 is 2,002,000 directions (~0.6 s for a
/// tetrahedron pair), gs-local 10 is 100 Ipopt solves (~7 s); beyond, one pair
/// takes minutes to hours (docs/scene-format.md).
inline constexpr int kMaxGrid = 1000;
inline constexpr int kMaxGsLocal = 10;

}  // namespace pd
