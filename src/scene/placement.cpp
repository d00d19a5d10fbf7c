#include "scene/placement.h"

#include <Eigen/SVD>

namespace pd {

Mat4 placement(const PartSpec& spec) {
  Mat4 m = spec.transform;
  m.topLeftCorner<3, 3>() *= spec.to_scene_units;
  return m;
}

Vec3 stretches(const Mat4& placement) {
  return Eigen::JacobiSVD<Eigen::Matrix3d>(placement.topLeftCorner<3, 3>()).singularValues();
}

double stretch(const Mat4& placement) {
  return stretches(placement)(0);
}

}  // namespace pd
