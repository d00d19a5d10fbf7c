#include "geometry/face_axes.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace pd {

Eigen::Matrix3d face_axes(const std::vector<std::array<Vec3, 3>>& triangles) {
  // Area per rounded normal (a map, so ties break the same way on every run).
  std::map<std::array<long, 3>, std::pair<Vec3, double>> groups;
  for (const auto& t : triangles) {
    const Vec3 c = (t[1] - t[0]).cross(t[2] - t[0]);
    const double area = 0.5 * c.norm();
    if (!(area > 0)) continue;
    const Vec3 n = c / (2 * area);
    const std::array<long, 3> key{std::lround(n.x() * 1000), std::lround(n.y() * 1000),
                                  std::lround(n.z() * 1000)};
    // (Eigen leaves a default vector uninitialised: the group starts at zero.)
    auto& [sum, total] = groups.try_emplace(key, Vec3::Zero(), 0.0).first->second;
    sum += area * n;  // the area-weighted mean normal of the group
    total += area;
  }
  if (groups.empty()) return Eigen::Matrix3d::Identity();
  std::vector<std::pair<double, Vec3>> by_area;
  for (const auto& [key, g] : groups) by_area.push_back({g.second, g.first.normalized()});
  std::stable_sort(by_area.begin(), by_area.end(),
                   [](const auto& x, const auto& y) { return x.first > y.first; });
  const Vec3 first = by_area.front().second;
  Vec3 second = first.unitOrthogonal();
  for (const auto& [area, n] : by_area)
    if (std::abs(n.dot(first)) < 0.2) {  // within about 12° of square
      second = (n - n.dot(first) * first).normalized();
      break;
    }
  Eigen::Matrix3d r;
  r.col(0) = first;
  r.col(1) = second;
  r.col(2) = first.cross(second);
  return r;
}

}  // namespace pd
