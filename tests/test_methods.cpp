// The depth methods (methods.cpp, solve_convex_pair) against the exact
// reference (the hull of the Minkowski difference): every method an upper
// bound. Each method's own tests: test_exact, test_mlsl, test_grid, test_epa.
#include <gtest/gtest.h>

#include "method_solve.h"
#include "solve/methods.h"

using namespace pd;
using pd_test::solve;

TEST(Methods, EveryMethodIsAnUpperBoundOnExact) {
  // Every method reports the gap at a real direction, so it can never be below
  // the true depth; the Ipopt methods land on the exact one on an easy case.
  SphereSampler r(3);
  for (int k = 0; k < 3; ++k) {
    const auto c = testgen::paper_like(r);
    const double exact = solve(c, Method::kExact).depth;
    for (Method m : {Method::kMlslPaper, Method::kGsLocal, Method::kGrid}) {
      const DepthSolution s = solve(c, m);
      EXPECT_GE(s.depth, exact * (1 - 1e-9)) << method_name(m);
      EXPECT_LE(s.depth, exact * 1.5) << method_name(m);
      EXPECT_TRUE(std::isfinite(s.depth));
    }
  }
}
