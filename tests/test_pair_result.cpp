// A pair's status (results/pair_result.cpp): its report names both ways and
// the classification of a depth against the tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>

#include "results/pair_result.h"
#include "tolerances.h"

using namespace pd;

TEST(PairResult, StatusNamesRoundTripAndAreDistinct) {
  const Status all[] = {Status::kSeparated, Status::kFalsePositive,      Status::kInterference,
                        Status::kError,     Status::kClearanceViolation, Status::kUndecided};
  std::set<std::string> names;
  for (const Status s : all) {
    const std::string n = status_name(s);
    EXPECT_TRUE(names.insert(n).second) << n;
    EXPECT_EQ(status_from_name(n), s) << n;
  }
  EXPECT_EQ(names, (std::set<std::string>{"separated", "false_positive", "interference", "error",
                                          "clearance_violation", "undecided"}));
  EXPECT_THROW(status_from_name("Interference"), std::invalid_argument);
  EXPECT_THROW(status_from_name(""), std::invalid_argument);
  EXPECT_TRUE(not_decided(Status::kError));
  EXPECT_TRUE(not_decided(Status::kUndecided));
  EXPECT_FALSE(not_decided(Status::kInterference));
  EXPECT_FALSE(not_decided(Status::kSeparated));
}

TEST(PairResult, ClassifyBandsScaleWithThePairSize) {
  const double t = 0.1;
  for (const double size : {1.0, 1e3, 1e6}) {
    const double touch = tol::kTouch * size, band = tol::kClassifyBand * size;
    EXPECT_EQ(classify(0.0, t, size), Status::kSeparated);
    EXPECT_EQ(classify(touch, t, size), Status::kSeparated);  // touching within rounding
    EXPECT_EQ(classify(std::nextafter(touch, 1.0) * 2, t, size), Status::kFalsePositive);
    EXPECT_EQ(classify(t, t, size), Status::kFalsePositive);
    EXPECT_EQ(classify(t + band, t, size), Status::kFalsePositive);  // rounding of tol
    EXPECT_EQ(classify(t + 2 * band + 1e-9, t, size), Status::kInterference);
    EXPECT_EQ(classify(1.0, t, size), Status::kInterference);
  }
}
