#include "batch/contact_band.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tolerances.h"

namespace pd {

namespace {

// The depth and witness are the parts' own, not a hull's or a piece pair's
// (whose witness can lie inside a part, away from every surface).
bool at_the_parts(const PairResult& r) {
  return r.at && (r.depth_source == "thickness" || r.depth_source == "surface");
}

}  // namespace

Status status_against(double lower, double upper, double t, double slack) {
  if (lower > t + slack) return Status::kInterference;
  if (upper <= t + slack) return Status::kFalsePositive;
  return Status::kUndecided;
}

void decide_at_contact(PairResult& r, const PairTolerance& wide) {
  const bool decided_by_band = r.status == Status::kFalsePositive ||
                               r.status == Status::kInterference || r.status == Status::kUndecided;
  if (!wide.at_contact || !decided_by_band || !at_the_parts(r)) return;
  const double lower = r.depth_bounds ? (*r.depth_bounds)[0] : r.depth;
  const double upper = r.depth_bounds ? (*r.depth_bounds)[1] : r.depth;
  const PairTolerance local = wide.at_contact(*r.at, contact_reach(upper, wide.value));
  if (!(local.value < wide.value)) return;
  const double slack = tol::kClassifyBand * wide.pair_size;
  Status s = status_against(lower, upper, local.value, slack);
  // An interference decided otherwise (the deepest surface point) stays one.
  if (r.status == Status::kInterference && s != Status::kInterference) s = Status::kUndecided;
  if (s == Status::kUndecided) {
    if (r.status != Status::kUndecided)
      r.tolerance_basis += "; decided against the band where the boxes meet: the depth bracket [" +
                           band_number(lower) + ", " + band_number(upper) +
                           "] does not decide against the band at the contact, " +
                           band_number(local.value);
    return;
  }
  if (r.status == Status::kUndecided) {  // the band at the contact decides it
    r.confirmed = true;
    r.reason.clear();
  }
  r.status = s;
  r.tolerance = local.value;
  r.tolerance_source = local.source;
  r.tolerance_basis = local.basis;
  r.margin = local.value - r.depth;
}

void note_gap_band(PairResult& r, const PairTolerance* band, const std::optional<Vec3>& at) {
  if (!band || !band->gap_at || !r.distance) return;
  const GapBand g = at ? band->gap_at(*at, contact_reach(*r.distance, band->value))
                       : band->gap_at(Vec3::Zero(), INFINITY);
  r.gap_band = g.value;
  r.gap_basis = g.basis;
}

ThicknessResult thickness_at_contact(const SolidDistance& a, const SolidDistance& b,
                                     double tolerance, const PairTolerance* band, double upper_hint,
                                     const std::function<std::optional<Vec3>()>& surface_at) {
  using Outcome = ThicknessResult::Outcome;
  ThicknessResult t = overlap_thickness(a, b, tolerance, upper_hint);
  if (!band || !band->at_contact || t.outcome != Outcome::kBelow) return t;
  const std::optional<Vec3> at = t.lower > 0 ? std::optional<Vec3>(t.at) : surface_at();
  if (!at) return t;  // no place known
  const double local = band->at_contact(*at, contact_reach(t.upper, tolerance)).value;
  // Touching to the coordinates' resolution is touching against any band.
  if (!(local < tolerance) || t.upper <= local || t.lower > local || t.upper <= t.resolution)
    return t;
  return thickness_again(a, b, t, local, tolerance);
}

ThicknessResult thickness_again(const SolidDistance& a, const SolidDistance& b,
                                const ThicknessResult& t, double threshold, double tolerance,
                                const ThicknessLimits& limits) {
  using Outcome = ThicknessResult::Outcome;
  ThicknessResult again = overlap_thickness(a, b, threshold, t.upper, limits);
  again.resolution = t.resolution;  // what the coordinates resolve: what is touching
  again.evaluations += t.evaluations;
  again.cells += t.cells;
  if (!(again.lower > t.lower)) {  // keep the better lower bound with its witness
    again.lower = t.lower;
    again.at = t.at;
    again.direction = t.direction;
  }
  again.upper = std::min(again.upper, t.upper);
  again.outcome = again.upper <= tolerance  ? Outcome::kBelow
                  : again.lower > tolerance ? Outcome::kAbove
                                            : again.outcome;
  return again;
}

}  // namespace pd
