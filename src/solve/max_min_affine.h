// The largest value over a box of the smallest of a few affine functions: the
// bound the overlap thickness takes over a cell from the planes of the two
// surfaces near it.
#pragma once

#include <vector>

#include "geometry/types.h"

namespace pd {

/// f(x) = value + slope·x.
struct Affine {
  double value = 0.0;
  Vec3 slope = Vec3::Zero();
};

/// An upper bound of max over the box [lo, hi] of min_k f_k(x), tight up to
/// rounding. It is the value of a dual point (weights λ ≥ 0 summing to 1, from a
/// small simplex solve): max over the box of Σ λ_k f_k, which bounds the min
/// from above for any λ, so rounding in the solve can loosen it but never make
/// it too low. +inf when `f` is empty.
double max_min_affine(const std::vector<Affine>& f, const Vec3& lo, const Vec3& hi);

/// A cheaper bound of the same: the smallest of the functions' own maxima over
/// the box (the dual point that puts all weight on one function). Never below
/// max_min_affine's value but for rounding; +inf when `f` is empty.
double min_max_affine(const std::vector<Affine>& f, const Vec3& lo, const Vec3& hi);

}  // namespace pd
