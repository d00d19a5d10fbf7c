#include "geometry/face_axes.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/huge_page_allocator.h"

namespace pd {

Eigen::Matrix3d face_axes(const std::vector<std::array<Vec3, 3>>& triangles) {
  return face_axes(triangles.data(), triangles.size());
}

namespace {

// The keys lie below 2001³ < 2³³: three stable counting passes of 11 bits,
// least significant first. The pairs come in face order, so faces of one key
// stay in that order: the same as sorting the pairs (a comparison sort of a
// fine sphere's faces was most of this function).
void sort_by_key(HugeVector<std::pair<std::uint64_t, std::uint32_t>>& order) {
  constexpr int kBits = 11, kPasses = 3;
  constexpr std::size_t kBuckets = std::size_t(1) << kBits;
  HugeVector<std::pair<std::uint64_t, std::uint32_t>> other(order.size());
  for (int pass = 0; pass < kPasses; ++pass) {
    const int shift = pass * kBits;
    std::array<std::size_t, kBuckets + 1> start{};
    for (const auto& e : order) ++start[((e.first >> shift) & (kBuckets - 1)) + 1];
    for (std::size_t b = 0; b < kBuckets; ++b) start[b + 1] += start[b];
    for (const auto& e : order) other[start[(e.first >> shift) & (kBuckets - 1)]++] = e;
    order.swap(other);
  }
}

}  // namespace

Eigen::Matrix3d face_axes(const std::array<Vec3, 3>* triangles, size_t count) {
  // Area per rounded normal: the faces sorted by their normal's key (then by
  // their order, so each group sums its faces in the order given), the groups
  // in key order, so ties break the same way on every run. (A fine sphere
  // makes a group per face: a sort, not a tree of nodes.) A unit normal's
  // rounded components lie in [-1000, 1000]: packed base 2001, the key's
  // order is theirs.
  HugeVector<std::pair<std::uint64_t, std::uint32_t>> order;  // key, face
  HugeVector<Vec3> weighted;                                  // area × unit normal
  HugeVector<double> area;
  order.reserve(count);
  weighted.reserve(count);
  area.reserve(count);
  for (size_t f = 0; f < count; ++f) {
    const std::array<Vec3, 3>& t = triangles[f];
    const Vec3 c = (t[1] - t[0]).cross(t[2] - t[0]);
    const double a = 0.5 * c.norm();
    if (!(a > 0)) continue;
    const Vec3 n = c / (2 * a);
    if (!n.allFinite()) continue;
    std::uint64_t key = 0;
    for (int k = 0; k < 3; ++k)
      key = key * 2001 + static_cast<std::uint64_t>(std::lround(n[k] * 1000) + 1000);
    order.push_back({key, static_cast<std::uint32_t>(weighted.size())});
    weighted.push_back(a * n);
    area.push_back(a);
  }
  sort_by_key(order);
  HugeVector<std::pair<double, Vec3>> by_area;
  by_area.reserve(order.size());
  for (size_t i = 0, j = 0; i < order.size(); i = j) {
    Vec3 sum = Vec3::Zero();  // the area-weighted mean normal of the group
    double total = 0.0;
    for (j = i; j < order.size() && order[j].first == order[i].first; ++j) {
      sum += weighted[order[j].second];
      total += area[order[j].second];
    }
    by_area.push_back({total, sum.normalized()});
  }
  if (by_area.empty()) return Eigen::Matrix3d::Identity();
  // The largest group, then the largest within about 12° of square to it; on
  // equal areas the earlier in key order (two scans: no sort of every group).
  const auto larger = [](const auto& x, const auto& y) { return x.first > y.first; };
  size_t top = 0;
  for (size_t k = 1; k < by_area.size(); ++k)
    if (larger(by_area[k], by_area[top])) top = k;
  const Vec3 first = by_area[top].second;
  Vec3 second = first.unitOrthogonal();
  size_t across = by_area.size();
  for (size_t k = 0; k < by_area.size(); ++k)
    if (std::abs(by_area[k].second.dot(first)) < 0.2 &&
        (across == by_area.size() || larger(by_area[k], by_area[across])))
      across = k;
  if (across < by_area.size()) {
    const Vec3& n = by_area[across].second;
    second = (n - n.dot(first) * first).normalized();
  }
  Eigen::Matrix3d r;
  r.col(0) = first;
  r.col(1) = second;
  r.col(2) = first.cross(second);
  return r;
}

}  // namespace pd
