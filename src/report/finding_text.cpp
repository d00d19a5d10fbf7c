#include "report/finding_text.h"

#include <cmath>
#include <cstdio>

namespace pd {

std::string short_number(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", x + 0.0);  // no -0
  return buf;
}

std::string depth_meaning(const std::string& depth_source) {
  if (depth_source == "thickness") return "overlap thickness";
  if (depth_source == "vertex") return "deepest vertex depth";
  if (depth_source == "surface") return "deepest surface point depth";
  if (depth_source == "pieces") return "piece depth";
  if (depth_source == "exact") return "overlap thickness of the exact solids";
  return "depth";
}

std::string exact_text(const ExactCheck& e, const std::string& depth_source,
                       const std::string& units) {
  const std::string how = exact_sentence(e);
  // Measured on the solids, the bracket is of their overlap thickness; widened
  // from the meshes, of what the mesh stage's depth is.
  const std::string what = e.basis == ExactBasis::kSolids || depth_source == "exact"
                               ? "overlap thickness"
                               : depth_meaning(depth_source);
  switch (e.verdict) {
    case ExactVerdict::kSkipped:
      return how;
    case ExactVerdict::kTouching:
      return "the exact solids touch (" + how + ")";
    case ExactVerdict::kSeparated:
      return "the exact solids are apart" +
             (e.distance ? " by " + short_number(*e.distance) + " " + units : std::string()) +
             " (" + how + ")";
    case ExactVerdict::kInterference:
    case ExactVerdict::kFalsePositive:
      if (!e.depth_bounds) return how;
      if (short_number((*e.depth_bounds)[0]) == short_number((*e.depth_bounds)[1]))
        return "the exact solids' " + what + " is " + short_number((*e.depth_bounds)[0]) + " " +
               units + " (" + how + ")";
      return "the exact solids' " + what + " is between " + short_number((*e.depth_bounds)[0]) +
             " and " + short_number((*e.depth_bounds)[1]) + " " + units + " (" + how + ")";
    default:
      return how;
  }
}

std::string finding_text(const PairResult& r, const std::vector<Part>& parts,
                         const PairReview& review, const std::string& units, double tolerance) {
  const std::string& a = parts[r.a].id;
  const std::string& b = parts[r.b].id;
  if (r.tolerance) tolerance = *r.tolerance;  // tolerance auto: the pair's own band
  std::string t = a + " / " + b + ": " + status_name(r.status);
  if (r.status == Status::kError) return t + ": " + r.error;
  // A unit vector: components below 1e-12 are rounding noise, shown as 0.
  auto c = [](double x) { return short_number(std::abs(x) < 1e-12 ? 0.0 : x); };
  const std::string dir =
      "(" + c(r.direction.x()) + ", " + c(r.direction.y()) + ", " + c(r.direction.z()) + ")";
  if (r.status == Status::kClearanceViolation && r.clearance_min && r.distance) {
    t += ": distance " + short_number(*r.distance) + " " + units;
    if (r.gap_band) t += " - gap band " + short_number(*r.gap_band) + " " + units;
    t += " < required clearance " + short_number(*r.clearance_min) + " " + units +
         "; separating normal " + dir;
    if (r.gap_band)
      t += "; the gap band is the tessellation's possible gap artefact (" + r.gap_basis + ")";
  } else if (r.status == Status::kSeparated && r.gap_band && r.distance &&
             *r.distance > 0) {  // a gap that the convex sags can make out of a contact
    t +=
        ": distance " + short_number(*r.distance) + " " + units +
        (*r.distance <= *r.gap_band ? " <= " : " > ") + "gap band " + short_number(*r.gap_band) +
        " " + units +
        (*r.distance <= *r.gap_band ? ", a contact within the tessellation's gap artefacts ("
                                    : ", clearance met beyond the tessellation's gap artefacts (") +
        r.gap_basis + ")";
  } else if (r.status == Status::kSeparated && r.depth_source == "hull") {
    t += "; separating normal " + dir;
  } else if (r.status == Status::kSeparated && r.depth_source == "mesh-test") {
    t += ": the hulls overlap, the parts' surfaces do not meet";
  } else if (r.status == Status::kSeparated) {  // a refined pair that only touches
    t += ": touching, " + depth_meaning(r.depth_source) + " at most " +
         short_number(r.depth_bounds ? (*r.depth_bounds)[1] : r.depth) + " " + units;
  } else if (r.status == Status::kUndecided) {
    const auto [lower, upper] = r.depth_bounds.value_or(std::array<double, 2>{r.depth, r.depth});
    t += ": depth between " + short_number(lower) + " and " + short_number(upper) + " " + units +
         ", tolerance " + short_number(tolerance) + " " + units + " (" + r.reason + ")";
  } else {
    t += ": " + depth_meaning(r.depth_source) + " " + short_number(r.depth) + " " + units +
         (r.status == Status::kInterference ? " > " : " <= ") + "tolerance " +
         short_number(tolerance) + " " + units;
    if (r.depth_bounds && r.depth_source != "hull")
      t += " (certified between " + short_number((*r.depth_bounds)[0]) + " and " +
           short_number((*r.depth_bounds)[1]) + " " + units + ")";
    // Only a convex pair's depth is a move that separates it; a nonconvex
    // pair's depth is a bound or a thickness (docs/solver.md).
    if (r.depth_source == "hull")
      t += "; moving " + b + " by the depth along " + dir + " separates the pair";
  }
  // B-rep pairs: what the verdict rests on, on the exact solids.
  if (r.exact) t += "; " + exact_text(*r.exact, r.depth_source, units);
  // Under tolerance auto, say what the band rests on: a false positive is
  // explained by the features whose tessellation can make that much overlap.
  if (r.tolerance && r.tolerance_source == "rule") {
    t += "; tolerance from rule " + r.tolerance_basis;
  } else if (r.tolerance && (r.status == Status::kFalsePositive ||
                             r.status == Status::kInterference || r.status == Status::kUndecided))
    t += (r.status == Status::kFalsePositive ? "; a tessellation artefact within the band of "
                                             : "; band from ") +
         r.tolerance_source + " sag (" + r.tolerance_basis + ")";
  if (review.baseline_state)
    t += "; baseline: " + std::string(baseline_state_name(*review.baseline_state));
  if (review.suppressed)
    t += "; suppressed" +
         (review.suppressed->rule.empty() ? "" : " by rule " + review.suppressed->rule) + ": " +
         review.suppressed->reason;
  else if (review.expected_exceeded)
    t += "; deeper than its expected-contact rule " + r.expected + " allows";
  return t;
}

}  // namespace pd
