#include "geometry/face_axes.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace pd {

Eigen::Matrix3d face_axes(const std::vector<std::array<Vec3, 3>>& triangles) {
  // Area per rounded normal: the faces sorted by their normal's key (then by
  // their order, so each group sums its faces in the order given), the groups
  // in key order, so ties break the same way on every run. (A fine sphere
  // makes a group per face: a sort, not a tree of nodes.)
  using Key = std::array<long, 3>;
  struct Face {
    Key key;
    size_t index;
    Vec3 weighted;  ///< area × unit normal
    double area;
  };
  std::vector<Face> faces;
  faces.reserve(triangles.size());
  for (const auto& t : triangles) {
    const Vec3 c = (t[1] - t[0]).cross(t[2] - t[0]);
    const double area = 0.5 * c.norm();
    if (!(area > 0)) continue;
    const Vec3 n = c / (2 * area);
    faces.push_back(
        {{std::lround(n.x() * 1000), std::lround(n.y() * 1000), std::lround(n.z() * 1000)},
         faces.size(),
         area * n,
         area});
  }
  std::sort(faces.begin(), faces.end(), [](const Face& x, const Face& y) {
    return x.key != y.key ? x.key < y.key : x.index < y.index;
  });
  std::vector<std::pair<double, Vec3>> by_area;
  for (size_t a = 0, b = 0; a < faces.size(); a = b) {
    Vec3 sum = Vec3::Zero();  // the area-weighted mean normal of the group
    double total = 0.0;
    for (b = a; b < faces.size() && faces[b].key == faces[a].key; ++b) {
      sum += faces[b].weighted;
      total += faces[b].area;
    }
    by_area.push_back({total, sum.normalized()});
  }
  if (by_area.empty()) return Eigen::Matrix3d::Identity();
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
