// The number a certified bracket shows (results/certified_decimal.h): inside
// the bracket, with the fewest significant digits, so that one overlap reads
// the same under brackets that differ in their last digits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "results/certified_decimal.h"

using pd::certified_decimal;

TEST(CertifiedDecimal, FewestDigitsInTheBracket) {
  EXPECT_EQ(certified_decimal(0.2, 0.4), 0.3);
  EXPECT_EQ(certified_decimal(0.2518, 0.3147), 0.3);
  EXPECT_EQ(certified_decimal(0.2343, 0.2684), 0.25);
  EXPECT_EQ(certified_decimal(0.04271, 0.04282), 0.0428);
  EXPECT_EQ(certified_decimal(1.0041, 1.0049), 1.0045);
  EXPECT_EQ(certified_decimal(0.0, 0.03), 0.0);
  EXPECT_EQ(certified_decimal(0.7, 0.7), 0.7);
  EXPECT_EQ(certified_decimal(0.1, 0.1 + 1e-17), 0.1);
  EXPECT_EQ(certified_decimal(95, 104), 100);
}

TEST(CertifiedDecimal, AOneMillimetreClashReadsOneWhereverItsBracketFalls) {
  // The brackets of one 1 mm lid clash at two placements (issue 44).
  EXPECT_EQ(certified_decimal(0.999849, 1.0084), 1.0);
  EXPECT_EQ(certified_decimal(0.999941, 1.0093), 1.0);
  EXPECT_EQ(certified_decimal(0.975428, 1.00814), 1.0);
}

TEST(CertifiedDecimal, NoShorterDecimalLiesInTheBracket) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> exponent(-6, 3), width(-8, 0), u(0, 1);
  char buf[40];
  for (int k = 0; k < 2000; ++k) {
    const double lower = std::pow(10.0, exponent(rng));
    const double upper = lower * (1 + std::pow(10.0, width(rng)) * u(rng));
    const double c = certified_decimal(lower, upper);
    ASSERT_GE(c, lower);
    ASSERT_LE(c, upper);
    // c's significant digits: the fewest n whose rounding gives c back.
    int n = 1;
    for (; n < 17; ++n) {
      std::snprintf(buf, sizeof buf, "%.*e", n - 1, c);
      if (std::strtod(buf, nullptr) == c) break;
    }
    if (n == 1) continue;
    // No multiple of one unit in the (n-1)-th digit lies in the bracket.
    const double unit = std::pow(10.0, std::floor(std::log10(upper)) - (n - 2));
    const double first = std::ceil(lower / unit) * unit;
    EXPECT_FALSE(first <= upper * (1 - 1e-15) && first >= lower * (1 + 1e-15))
        << lower << " " << upper << " -> " << c << " but " << first;
  }
}
