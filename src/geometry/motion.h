// Rigid motion of a part over time: a rotation at constant angular velocity
// about an axis through a point, plus a constant linear velocity.
//   x(t) = R(ω·t)·(x − about) + about + velocity·t
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

#include "geometry/types.h"

namespace pd {

struct RigidMotion {
  Vec3 angular = Vec3::Zero();   ///< ω, rad per second; its direction is the axis
  Vec3 about = Vec3::Zero();     ///< a point of the axis, scene units
  Vec3 velocity = Vec3::Zero();  ///< scene units per second

  Points at(const Points& x, double t) const {
    const double w = angular.norm();
    const Eigen::Matrix3d r = w > 0 ? Eigen::AngleAxisd(w * t, angular / w).toRotationMatrix()
                                    : Eigen::Matrix3d::Identity();
    Points out = r * (x.colwise() - about);
    out.colwise() += about + velocity * t;
    return out;
  }
};

/// The most grid times a motion check may have (docs/scene-format.md).
inline constexpr long kMaxTimeSteps = 1000000;

/// The time grid of a motion check: t0, t0 + dt, …, up to t1 (inclusive, within
/// rounding).
struct TimeGrid {
  double t0 = 0.0, t1 = 0.0, dt = 1.0;
  /// At most kMaxTimeSteps (scenes are checked when read): a larger count is
  /// refused, never cast out of range (that wrapped and skipped the check).
  long steps() const {
    const double n = step_count();
    if (!(n >= 1 && n <= kMaxTimeSteps))
      throw std::domain_error("the time grid has no or more than 1,000,000 steps");
    return static_cast<long>(n);
  }
  /// The number of grid times in double precision, unchecked: a cast of more
  /// than 2^63 steps to an integer would be undefined (scene_json.cpp checks this).
  double step_count() const { return std::floor((t1 - t0) / dt + 1e-9) + 1; }
  double time(long k) const { return t0 + dt * static_cast<double>(k); }
};

}  // namespace pd
