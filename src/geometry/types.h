// Basic geometric types shared by every module.
#pragma once

#include <Eigen/Core>

namespace pd {

using Vec3 = Eigen::Vector3d;
/// A point set: one column per point (3 × n, column-major, so a point is contiguous).
using Points = Eigen::Matrix<double, 3, Eigen::Dynamic>;
using Mat4 = Eigen::Matrix4d;

}  // namespace pd
