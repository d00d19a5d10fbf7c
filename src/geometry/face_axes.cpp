#include "geometry/face_axes.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace pd {

Eigen::Matrix3d face_axes(const std::vector<std::array<Vec3, 3>>& triangles) {
  // Area per rounded normal. Grouped by hash (a fine sphere has a group per
  // triangle), then put in key order, so ties break the same way on every run;
  // each group sums its triangles in their order.
  using Key = std::array<long, 3>;
  struct KeyHash {
    size_t operator()(const Key& k) const {
      uint64_t h = 0x9e3779b97f4a7c15ull;
      for (long x : k) h = (h ^ static_cast<uint64_t>(x)) * 0xff51afd7ed558ccdull;
      return static_cast<size_t>(h ^ (h >> 33));
    }
  };
  std::unordered_map<Key, size_t, KeyHash> index;
  index.reserve(triangles.size());
  std::vector<std::pair<Key, std::pair<Vec3, double>>> found;
  for (const auto& t : triangles) {
    const Vec3 c = (t[1] - t[0]).cross(t[2] - t[0]);
    const double area = 0.5 * c.norm();
    if (!(area > 0)) continue;
    const Vec3 n = c / (2 * area);
    const Key key{std::lround(n.x() * 1000), std::lround(n.y() * 1000), std::lround(n.z() * 1000)};
    const auto [it, added] = index.try_emplace(key, found.size());
    if (added) found.push_back({key, {Vec3::Zero(), 0.0}});
    auto& [sum, total] = found[it->second].second;
    sum += area * n;  // the area-weighted mean normal of the group
    total += area;
  }
  std::sort(found.begin(), found.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::pair<double, Vec3>> by_area;
  by_area.reserve(found.size());
  for (const auto& [key, g] : found) by_area.push_back({g.second, g.first.normalized()});
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
