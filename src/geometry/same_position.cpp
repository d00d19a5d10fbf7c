#include "geometry/same_position.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pd {

std::vector<int> first_at_same_position(const Points& p) {
  const int n = static_cast<int>(p.cols());
  std::vector<int> first(static_cast<size_t>(n));
  std::iota(first.begin(), first.end(), 0);
  // NaN would break the sort's ordering: non-finite columns stay their own.
  // The coordinates are sorted with their column, side by side in memory (an
  // index sort reading p at random was most of a fine part's welding checks).
  struct Column {
    double x, y, z;
    int i;
  };
  std::vector<Column> order;
  order.reserve(first.size());
  for (int i = 0; i < n; ++i)
    if (p.col(i).allFinite()) order.push_back({p(0, i), p(1, i), p(2, i), i});
  std::sort(order.begin(), order.end(), [](const Column& a, const Column& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    if (a.z != b.z) return a.z < b.z;
    return a.i < b.i;  // within a run of equal points, the first column leads
  });
  for (size_t k = 1; k < order.size(); ++k) {
    const Column &a = order[k - 1], &b = order[k];
    if (a.x == b.x && a.y == b.y && a.z == b.z) first[size_t(b.i)] = first[size_t(a.i)];
  }
  return first;
}

long boundary_edges(const Mesh& m) {
  const std::vector<int> first = first_at_same_position(m.vertices);
  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * static_cast<size_t>(m.triangles.cols()));
  for (Eigen::Index t = 0; t < m.triangles.cols(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int u = first[m.triangles(k, t)], v = first[m.triangles((k + 1) % 3, t)];
      if (u != v) edges.emplace_back(std::min(u, v), std::max(u, v));
    }
  std::sort(edges.begin(), edges.end());
  long odd = 0;
  for (size_t k = 0; k < edges.size();) {
    size_t end = k;
    while (end < edges.size() && edges[end] == edges[k]) ++end;
    odd += (end - k) % 2;
    k = end;
  }
  return odd;
}

}  // namespace pd
