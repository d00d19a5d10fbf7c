// The EPA bracket (solve/epa.h) checked against the exact reference on one pair:
// lower <= exact <= upper always, and a certified bracket's depth (upper) equal
// to exact's within the bracket's width. Shared by the EPA and hard-case tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "solve/epa.h"
#include "solve/exact.h"
#include "tolerances.h"

namespace pd::testing {

struct BracketTally {
  int pairs = 0, certified = 0, separated = 0;
};

/// The exact reference's own rounding (qhull's facet offsets, its closest
/// point): the slack allowed on its side of each comparison. It is of the
/// order of kGapRounding, the rounding of a gap at unit scale below which a
/// depth counts as contact: a touching pair's exact depth of 1.4e-14 and a
/// bracket's upper end of 0.94e-14 differ by rounding alone (seen under clang
/// with ASan: its code rounds differently from gcc's at that level).
inline constexpr double kExactRounding = tol::kGapRounding;

inline void expect_bracket_holds(const std::string& what, const Points& a, const Points& b,
                                 BracketTally* tally = nullptr) {
  const PairProblem pr(a, b);
  const DepthSolution e = exact_depth(pr.p(), pr.q());
  // The signed minimum of the gap: the depth, or minus the separation distance;
  // a contact within rounding (depth 0, distance 0) is known only to lie in
  // [−kTouch, kGapRounding] (solve/exact.cpp).
  const bool contact = e.depth == 0 && e.distance.value_or(0.0) == 0;
  const double exact = e.depth > 0 ? e.depth : -e.distance.value_or(0.0);
  const double exact_low = contact ? -tol::kTouch : exact;
  const double exact_high = contact ? tol::kGapRounding : exact;
  const DepthBracket br = epa_bracket(pr, tol::kEpaMaxIterations);
  char text[200];
  std::snprintf(text, sizeof text, "%s: exact %.17g, bracket [%.17g, %.17g]%s%s", what.c_str(),
                exact, br.lower, br.upper, br.certified() ? " certified" : "",
                br.separated ? " separated" : "");
  SCOPED_TRACE(text);
  EXPECT_LE(br.lower, exact_high + kExactRounding);
  EXPECT_GE(br.upper, exact_low - kExactRounding);
  if (br.separated) {
    EXPECT_LE(exact, tol::kGapRounding);
  }
  if (br.certified() && !contact) {
    EXPECT_LE(std::abs(br.upper - exact), tol::kEpaBracket + kExactRounding);
  }
  if (tally) {
    ++tally->pairs;
    tally->certified += br.certified();
    tally->separated += br.separated;
  }
}

}  // namespace pd::testing
