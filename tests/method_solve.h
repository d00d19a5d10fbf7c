// One pair solved by a named method with default settings, the gap at a
// direction in world units, and a cube: shared by the method tests
// (test_methods, test_exact, test_mlsl).
#pragma once

#include <cstdint>

#include "corpus/generators.h"
#include "solve/methods.h"

namespace pd_test {

inline double gap_world(const pd::Points& a, const pd::Points& b, const pd::Vec3& v) {
  return (v.transpose() * a).maxCoeff() - (v.transpose() * b).minCoeff();
}

inline pd::DepthSolution solve(const pd::testgen::PairCase& c, pd::Method m,
                               std::uint64_t seed = 1) {
  static pd::IpoptLocalSolver ipopt;
  pd::SolverSettings s;
  s.method = m;
  s.seed = seed;
  return pd::solve_convex_pair(c.a, c.b, s, ipopt);
}

/// The cube of half-size h about c.
inline pd::Points cube(double h, const pd::Vec3& c) {
  pd::Points p(3, 8);
  for (int k = 0; k < 8; ++k)
    p.col(k) = c + h * pd::Vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
  return p;
}

}  // namespace pd_test
