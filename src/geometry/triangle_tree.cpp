#include "geometry/triangle_tree.h"

#include <algorithm>
#include <numeric>

namespace pd {

Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

namespace {

// A leaf of a few triangles: fewer nodes to visit, and a triangle's test costs
// about as much as a box's.
constexpr int kLeafSize = 4;

double box_squared_distance(const Vec3& lo, const Vec3& hi, const Vec3& p) {
  return (lo - p).cwiseMax(p - hi).cwiseMax(0.0).squaredNorm();
}

}  // namespace

TriangleTree::TriangleTree(const std::vector<std::array<Vec3, 3>>& triangles)
    : triangles_(triangles), id_(triangles.size()), slot_(triangles.size()) {
  if (triangles.empty()) return;
  std::iota(id_.begin(), id_.end(), 0);
  std::vector<Vec3> centroids(triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i)
    centroids[i] = (triangles[i][0] + triangles[i][1] + triangles[i][2]) / 3;
  nodes_.reserve(2 * triangles.size() / kLeafSize + 2);
  build(0, static_cast<int>(triangles.size()), centroids);
  for (size_t i = 0; i < id_.size(); ++i) triangles_[i] = triangles[id_[i]];
  for (size_t i = 0; i < id_.size(); ++i) slot_[id_[i]] = static_cast<int>(i);
  boxes_.resize(triangles_.size());
  for (size_t i = 0; i < triangles_.size(); ++i) {
    const auto& t = triangles_[i];
    boxes_[i] = {t[0].cwiseMin(t[1]).cwiseMin(t[2]), t[0].cwiseMax(t[1]).cwiseMax(t[2])};
  }
}

void TriangleTree::in_box(const Vec3& lo, const Vec3& hi, std::vector<int>& out,
                          size_t limit) const {
  if (triangles_.empty()) return;
  const auto meets = [&](const Vec3& a, const Vec3& b) {
    return (a.array() <= hi.array()).all() && (lo.array() <= b.array()).all();
  };
  const size_t before = out.size();
  std::array<int, 2 * 32 + 2> stack;  // as in nearest()
  int size = 0;
  stack[size++] = 0;
  while (size > 0) {
    const int at = stack[--size];
    const Node& n = nodes_[at];
    if (!meets(n.lo, n.hi)) continue;
    if (n.count > 0) {
      for (int i = n.first; i < n.first + n.count; ++i)
        if (meets(boxes_[i][0], boxes_[i][1])) {
          out.push_back(id_[i]);
          if (out.size() - before > limit) return;
        }
      continue;
    }
    stack[size++] = n.first;
    stack[size++] = at + 1;
  }
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(before), out.end());
}

// Median split of the centroids along their longest extent.
int TriangleTree::build(int begin, int end, const std::vector<Vec3>& centroids) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  Vec3 clo = lo, chi = hi;
  for (int i = begin; i < end; ++i) {
    for (const Vec3& v : triangles_[id_[i]]) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    clo = clo.cwiseMin(centroids[id_[i]]), chi = chi.cwiseMax(centroids[id_[i]]);
  }
  nodes_[index].lo = lo;
  nodes_[index].hi = hi;
  if (end - begin <= kLeafSize) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  int axis = 0;
  (chi - clo).maxCoeff(&axis);
  const int mid = begin + (end - begin) / 2;
  std::nth_element(id_.begin() + begin, id_.begin() + mid, id_.begin() + end,
                   [&](int x, int y) { return centroids[x][axis] < centroids[y][axis]; });
  build(begin, mid, centroids);  // the first child follows its parent
  const int second = build(mid, end, centroids);
  nodes_[index].first = second;
  return index;
}

TriangleTree::Nearest TriangleTree::nearest(const Vec3& p, int start) const {
  Nearest best;
  if (triangles_.empty()) return best;
  const auto test = [&](int slot) {
    const auto& t = triangles_[slot];
    const Vec3 q = closest_on_triangle(p, t[0], t[1], t[2]);
    const double d2 = (q - p).squaredNorm();
    if (d2 < best.squared_distance) best = {q, id_[slot], d2};
  };
  if (start >= 0 && start < static_cast<int>(slot_.size())) test(slot_[start]);
  // Depth first, the nearer child first; a node no nearer than the best is
  // skipped. Each visit pushes at most two nodes, one level down, and median
  // splits keep the depth below 32: the stack never holds more than 64.
  std::array<int, 2 * 32 + 2> stack;
  int size = 0;
  stack[size++] = 0;
  while (size > 0) {
    const int at = stack[--size];
    const Node& n = nodes_[at];
    if (!(box_squared_distance(n.lo, n.hi, p) < best.squared_distance)) continue;
    if (n.count > 0) {
      for (int i = n.first; i < n.first + n.count; ++i) test(i);
      continue;
    }
    const int left = at + 1, right = n.first;
    const double dl = box_squared_distance(nodes_[left].lo, nodes_[left].hi, p),
                 dr = box_squared_distance(nodes_[right].lo, nodes_[right].hi, p);
    // Pushed last is searched first.
    if (dl < dr) {
      if (dr < best.squared_distance) stack[size++] = right;
      if (dl < best.squared_distance) stack[size++] = left;
    } else {
      if (dl < best.squared_distance) stack[size++] = left;
      if (dr < best.squared_distance) stack[size++] = right;
    }
  }
  return best;
}

}  // namespace pd
