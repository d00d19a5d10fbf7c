// The paper's 5-variable local problem, solved by Ipopt:
//   min α  s.t.  q_j·v − c + α >= 0,  p_i·v − c <= 0,  v·v = 1,  α >= 0.
// Only v·v = 1 is nonlinear, so the Hessian of the Lagrangian is 2λ·I on v.
#pragma once

#include <memory>
#include <vector>

#include "geometry/types.h"

namespace pd {

struct LocalStart {
  Vec3 v;
  double c = 0.0;
  double alpha = 0.0;
};

struct LocalOutcome {
  Vec3 v = Vec3::UnitZ();  ///< normalised
  double c = 0.0;
  double alpha = 0.0;
  int iterations = 0;
  bool converged = false;
  std::string status;  ///< Ipopt's return status, for the report when it failed
};

/// One Ipopt application, initialised once and reused for every solve of a
/// process (Debian's Ipopt 3.11 with MUMPS is not thread-safe: one per process).
class IpoptLocalSolver {
 public:
  IpoptLocalSolver();
  ~IpoptLocalSolver();
  IpoptLocalSolver(const IpoptLocalSolver&) = delete;
  IpoptLocalSolver& operator=(const IpoptLocalSolver&) = delete;

  /// Solves over the vertex subsets `pi` of p and `qj` of q (all_indices() for
  /// the paper's full problem). `warm` starts with a small barrier: for starts
  /// next to an optimum. `alpha_free` drops α >= 0: α is then the signed gap,
  /// and its minimum minus the separation distance of a separated pair (Zhou
  /// et al.'s NLP for the minimum translational distance).
  LocalOutcome solve(const Points& p, const Points& q, const std::vector<int>& pi,
                     const std::vector<int>& qj, const LocalStart& start, bool warm,
                     bool alpha_free = false);

  /// The start of the paper's Algorithm 2: c0 = max p·v0, α0 = c0 − min q·v0.
  static LocalStart paper_start(const Points& p, const Points& q, const Vec3& v0);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

std::vector<int> all_indices(Eigen::Index n);

}  // namespace pd
