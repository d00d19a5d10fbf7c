#include "geometry/cluster_vertices.h"

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <tuple>
#include <vector>

namespace pd {

Mesh cluster_vertices(const Mesh& mesh, int cells) {
  const long n = mesh.vertices.cols();
  if (n == 0) return mesh;
  const Vec3 lo = mesh.vertices.rowwise().minCoeff(), hi = mesh.vertices.rowwise().maxCoeff();
  const double size = std::max((hi - lo).maxCoeff(), 1e-300) / cells;
  std::map<std::tuple<long, long, long>, int> cell_of;
  std::vector<int> new_id(static_cast<size_t>(n));
  std::vector<Vec3> sum;
  std::vector<int> count;
  for (long k = 0; k < n; ++k) {
    const Vec3 q = ((mesh.vertices.col(k) - lo) / size).array().floor();
    const auto key =
        std::make_tuple(static_cast<long>(q[0]), static_cast<long>(q[1]), static_cast<long>(q[2]));
    auto [it, added] = cell_of.emplace(key, static_cast<int>(sum.size()));
    if (added) {
      sum.push_back(Vec3::Zero());
      count.push_back(0);
    }
    sum[static_cast<size_t>(it->second)] += mesh.vertices.col(k);
    ++count[static_cast<size_t>(it->second)];
    new_id[static_cast<size_t>(k)] = it->second;
  }
  std::set<std::array<int, 3>> seen;
  std::vector<std::array<int, 3>> kept;
  for (long t = 0; t < mesh.triangles.cols(); ++t) {
    std::array<int, 3> tri{};
    for (int c = 0; c < 3; ++c) tri[c] = new_id[static_cast<size_t>(mesh.triangles(c, t))];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
    std::array<int, 3> key = tri;
    std::sort(key.begin(), key.end());
    if (seen.insert(key).second) kept.push_back(tri);
  }
  Mesh out;
  out.vertices.resize(3, static_cast<long>(sum.size()));
  for (size_t k = 0; k < sum.size(); ++k)
    out.vertices.col(static_cast<long>(k)) = sum[k] / count[k];
  out.triangles.resize(3, static_cast<long>(kept.size()));
  for (size_t t = 0; t < kept.size(); ++t)
    for (int c = 0; c < 3; ++c) out.triangles(c, static_cast<long>(t)) = kept[t][c];
  return out;
}

}  // namespace pd
