#include "solve/methods.h"

#include <stdexcept>

#include "solve/exact.h"
#include "solve/grid.h"
#include "solve/mlsl.h"
#include "solve/objective.h"

namespace pd {

std::optional<Method> parse_method(const std::string& name) {
  if (name == "mlsl") return Method::kMlsl;
  if (name == "mlsl-paper") return Method::kMlslPaper;
  if (name == "gs-local") return Method::kGsLocal;
  if (name == "grid") return Method::kGrid;
  if (name == "exact") return Method::kExact;
  return std::nullopt;
}

std::string method_name(Method m) {
  switch (m) {
    case Method::kMlsl:
      return "mlsl";
    case Method::kMlslPaper:
      return "mlsl-paper";
    case Method::kGsLocal:
      return "gs-local";
    case Method::kGrid:
      return "grid";
    case Method::kExact:
      return "exact";
  }
  return "?";
}

const char* stop_reason_name(StopReason r) {
  switch (r) {
    case StopReason::kNone:
      return "none";
    case StopReason::kProvenSeparated:
      return "proven_separated";
    case StopReason::kContact:
      return "contact";
    case StopReason::kEpaCertificate:
      return "epa-certificate";
    case StopReason::kCertificate:
      return "certificate";
    case StopReason::kBayesian:
      return "bayesian";
    case StopReason::kCap:
      return "cap";
    case StopReason::kAboveTolerance:
      return "above_tolerance";
  }
  return "none";
}

DepthSolution solve_convex_pair(const Points& a, const Points& b, const SolverSettings& s,
                                IpoptLocalSolver& ipopt) {
  const PairProblem pr(a, b);
  DepthSolution sol;
  switch (s.method) {
    case Method::kExact:
      sol = exact_depth(pr.p(), pr.q());
      break;
    case Method::kMlsl: {
      const InputPoints input{a, b};
      sol = mlsl_depth(pr, ipopt, s, &input);
      break;
    }
    case Method::kMlslPaper:
      sol = mlsl_paper_depth(pr, ipopt, s);
      break;
    case Method::kGsLocal:
      sol = gs_local_depth(pr, ipopt, s.gs_local);
      break;
    case Method::kGrid:
      sol = grid_depth(pr, s.grid);
      break;
  }
  if (!sol.fallback.empty() || !std::isfinite(sol.depth) || !sol.direction.allFinite()) {
    // Never a "clean" answer from a failed solve: the exact reference decides.
    const std::string why = sol.fallback.empty() ? "non-finite result" : sol.fallback;
    const SolveStats stats = sol.stats;
    sol = exact_depth(pr.p(), pr.q());
    sol.stats = stats;
    sol.fallback = "exact, because " + why;
  }
  if (!std::isfinite(sol.depth)) throw std::runtime_error("depth is not finite");
  sol.depth = pr.frame().length_to_world(sol.depth);
  if (sol.distance) sol.distance = pr.frame().length_to_world(*sol.distance);
  return sol;
}

}  // namespace pd
