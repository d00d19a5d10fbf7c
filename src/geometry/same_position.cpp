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
  std::vector<int> order;
  order.reserve(first.size());
  for (int i = 0; i < n; ++i)
    if (p.col(i).allFinite()) order.push_back(i);
  const auto same = [&](int a, int b) {
    return p(0, a) == p(0, b) && p(1, a) == p(1, b) && p(2, a) == p(2, b);
  };
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    for (int k = 0; k < 3; ++k)
      if (p(k, a) != p(k, b)) return p(k, a) < p(k, b);
    return a < b;  // within a run of equal points, the first column leads
  });
  for (size_t k = 1; k < order.size(); ++k)
    if (same(order[k], order[k - 1])) first[order[k]] = first[order[k - 1]];
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
