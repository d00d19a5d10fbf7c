// Uniformly random rotations for the suites that turn their cases.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "solve/mlsl.h"

namespace pd_test {

/// A normalised Gaussian quaternion: uniform over the rotations.
inline Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}

/// A random angle about a random axis (the exact-depth suites' draws).
inline Eigen::Matrix3d random_rotation(pd::SphereSampler& r) {
  return Eigen::AngleAxisd(2 * M_PI * r.uniform(), r.direction()).toRotationMatrix();
}

}  // namespace pd_test
