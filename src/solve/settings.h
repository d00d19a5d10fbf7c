// Depth methods and their settings (CLI --method, the scene's "solver" block).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace pd {

enum class Method { kMlsl, kMlslPaper, kGsLocal, kGrid, kExact };

std::optional<Method> parse_method(const std::string& name);
std::string method_name(Method m);

/// A setting added here is listed once more, in for_each_setting below: every
/// hash and the report follow it (tests/test_settings_hashes.cpp).
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
  /// mlsl: start with the GJK + EPA bracket (solve/epa.h), final when it closes.
  /// No scene, CLI or report key: the tests of the sampling path itself turn it
  /// off. The one setting outside for_each_setting: add_solver_settings
  /// (batch/content_hashes.h) hashes it when off, so the default's hashes hold.
  bool epa = true;
  int max_local_solves = 60;
  double max_seconds = 30.0;

  // mlsl-paper: the paper's Algorithm 1 with its parameters.
  int paper_n = 10;
  int paper_m = 3;

  int grid = 40;     ///< grid: GS-k, 2k(k+1) directions, k per π in each angle
  int gs_local = 3;  ///< gs-local: a k×k grid of Ipopt starts (the paper's GS-SQP)
};

/// One setting's names: its key (hashes) and, when the report's "method" block
/// shows it, the key there and the methods whose block does.
struct Setting {
  const char* key;
  const char* report_key = nullptr;  ///< nullptr: not in the report
  unsigned methods = 0;              ///< bits 1 << Method: the blocks that show it

  constexpr bool reported_for(Method m) const {
    return report_key && (methods & (1u << static_cast<unsigned>(m)));
  }
};

/// The one list of the settings, for everything that hashes or writes them all
/// (the settings hash, the refinement cache key, the report's "method" block):
/// `visit(Setting, member)` on a const or a mutable SolverSettings. Integers come
/// before doubles (the settings hash has always hashed them in that order).
template <class S, class Visit>
void for_each_setting(S& s, Visit&& visit) {
  constexpr unsigned all = ~0u;
  constexpr unsigned mlsl = 1u << static_cast<unsigned>(Method::kMlsl);
  constexpr unsigned paper = 1u << static_cast<unsigned>(Method::kMlslPaper);
  constexpr unsigned grid = 1u << static_cast<unsigned>(Method::kGrid);
  constexpr unsigned gs_local = 1u << static_cast<unsigned>(Method::kGsLocal);
  visit(Setting{"method", "name", all}, s.method);
  visit(Setting{"seed", "seed", all}, s.seed);
  visit(Setting{"samples", "samples", mlsl}, s.samples);
  visit(Setting{"min_iterations"}, s.min_iterations);
  visit(Setting{"max_iterations"}, s.max_iterations);
  visit(Setting{"max_local_solves"}, s.max_local_solves);
  visit(Setting{"paper_n", "N", paper}, s.paper_n);
  visit(Setting{"paper_m", "M", paper}, s.paper_m);
  visit(Setting{"grid", "grid", grid}, s.grid);
  visit(Setting{"gs_local", "gs_local", gs_local}, s.gs_local);
  visit(Setting{"reduced", "reduced", mlsl}, s.reduced);
  visit(Setting{"sigma", "sigma", mlsl | paper}, s.sigma);
  visit(Setting{"tau", "tau", mlsl | paper}, s.tau);
  visit(Setting{"link_scale", "link_scale", mlsl}, s.link_scale);
  visit(Setting{"max_seconds"}, s.max_seconds);
}

/// Largest k a scene may give: GS-1000 is 2,002,000 directions (~0.6 s for a
/// tetrahedron pair), gs-local 10 is 100 Ipopt solves (~7 s); beyond, one pair
/// takes minutes to hours (docs/scene-format.md).
inline constexpr int kMaxGrid = 1000;
inline constexpr int kMaxGsLocal = 10;

}  // namespace pd
