// The objective of Abramson, Kent & Smith on centred, scaled coordinates.
//
// For a pair (P, Q) and a unit direction v,
//   gap(v)   = max_i p_i·v − min_j q_j·v   (= h_{P−Q}(v), the support function of P − Q)
//   alpha(v) = max(0, gap(v))              (the paper's 2-variable objective)
// The minimum of gap over the sphere is the signed minimum translational
// distance: the penetration depth when the hulls overlap, minus the separation
// distance when they do not. Moving Q by alpha(v)·v separates the pair.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "geometry/frame.h"
#include "geometry/types.h"
#include "solve/support_scan.h"

namespace pd {

/// A point of P − Q by its parts' vertex indices: p_i − q_j (a_i − b_j in the
/// world), so that it can be recomputed from the input coordinates.
struct MinkowskiIndex {
  int i = -1, j = -1;
};

/// A pair in its unit frame (see geometry/frame.h). P is part a, Q is part b.
class PairProblem {
 public:
  PairProblem(const Points& a_world, const Points& b_world);

  const Points& p() const { return p_; }
  const Points& q() const { return q_; }
  const Frame& frame() const { return frame_; }
  /// p and q as coordinate arrays, for support values without a temporary.
  const SoaPoints& p_soa() const { return p_soa_; }
  const SoaPoints& q_soa() const { return q_soa_; }

  /// gap(v) in O(n + m); counts one evaluation.
  double gap(const Vec3& v) const;
  double alpha(const Vec3& v) const { return std::max(0.0, gap(v)); }
  /// gap(v), bit for bit, and the support point p_i − q_j of P − Q at v (the
  /// first extreme vertices, as gap finds them); counts one evaluation.
  double support(const Vec3& v, Vec3& point) const;
  /// The same, with the indices (i, j) of the two vertices: point = p_i − q_j.
  double support(const Vec3& v, Vec3& point, MinkowskiIndex& id) const;
  /// gap(v[k]) for k < count into out, bit for bit; counts `count` evaluations.
  void gaps(const Vec3* v, size_t count, double* out) const;
  long evaluations() const { return evaluations_; }

 private:
  Frame frame_;
  Points p_, q_;
  SoaPoints p_soa_, q_soa_;
  mutable long evaluations_ = 0;
};

/// Indices of the points whose support value x·v lies within `band` of the
/// extreme: the largest (top = true, for P) or the smallest (for Q). These are
/// the vertices active, or able to become active, at direction v.
std::vector<int> near_extreme(const Points& x, const Vec3& v, double band, bool top);

/// Spherical coordinates of the paper, eq. (3): θ is longitude, φ latitude.
inline Vec3 direction_from_angles(double theta, double phi) {
  return {std::cos(theta) * std::cos(phi), std::sin(theta) * std::cos(phi), std::sin(phi)};
}

/// The inverse map (the paper's Algorithm 2, steps 6–7, with atan2 so that the
/// quadrant survives): θ in [0, 2π), φ in [−π/2, π/2]. At the poles θ is
/// undetermined; like the paper we always return π/2 there, so one direction
/// has one pair of angles.
void angles_from_direction(const Vec3& v, double& theta, double& phi);

/// Angle between two unit vectors, accurate for small and large angles alike.
double angle_between(const Vec3& a, const Vec3& b);

}  // namespace pd
