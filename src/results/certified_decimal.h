// The digits a certified bracket supports: a depth known to lie in [lower,
// upper] is shown as the decimal with the fewest significant digits in that
// bracket, so that a number never claims more than its certificate, and the
// same overlap reads the same wherever its parts sit (a 1 mm clash bracketed
// [0.99985, 1.0084] at one place and [0.99994, 1.0091] at another reads 1).
#pragma once

namespace pd {

/// The double nearest the decimal with the fewest significant digits in
/// [lower, upper] (among those, the nearest the bracket's middle); 0 when the
/// bracket holds 0. lower ≤ upper, both finite.
double certified_decimal(double lower, double upper);

}  // namespace pd
