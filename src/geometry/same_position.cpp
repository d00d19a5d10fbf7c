#include "geometry/same_position.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>

namespace pd {

namespace {

// −0 and 0 hash alike (x + 0.0 is +0 for both); a finite coordinate only.
std::uint64_t bits_of(double x) {
  x += 0.0;
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// splitmix64's finaliser: every input bit moves every output bit, so columns
// that differ in their last mantissa bits (float32 neighbours) spread too.
std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace

std::vector<int> first_at_same_position(const Points& p) {
  const int n = static_cast<int>(p.cols());
  std::vector<int> first(static_cast<size_t>(n));
  std::iota(first.begin(), first.end(), 0);
  // Columns go in in index order, so the one a slot holds is the first of its
  // position. NaN equals nothing: non-finite columns stay their own.
  size_t capacity = 16;
  while (capacity < 2 * static_cast<size_t>(n)) capacity *= 2;
  std::vector<int> slot(capacity, -1);
  const size_t mask = capacity - 1;
  for (int i = 0; i < n; ++i) {
    const double x = p(0, i), y = p(1, i), z = p(2, i);
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) continue;
    size_t h = mix(bits_of(x) ^ mix(bits_of(y) ^ mix(bits_of(z)))) & mask;
    for (;; h = (h + 1) & mask) {
      const int j = slot[h];
      if (j < 0) {
        slot[h] = i;
        break;
      }
      if (p(0, j) == x && p(1, j) == y && p(2, j) == z) {
        first[size_t(i)] = j;
        break;
      }
    }
  }
  return first;
}

Points distinct_positions(const Points& p, const std::vector<int>& first) {
  Eigen::Index n = 0;
  for (size_t i = 0; i < first.size(); ++i) n += first[i] == static_cast<int>(i);
  Points out(3, n);
  n = 0;
  for (size_t i = 0; i < first.size(); ++i)
    if (first[i] == static_cast<int>(i)) out.col(n++) = p.col(static_cast<Eigen::Index>(i));
  return out;
}

Mesh welded(const Mesh& m, const std::vector<int>& first) {
  std::vector<int> number(first.size());
  int n = 0;
  for (size_t i = 0; i < first.size(); ++i)
    number[i] = first[i] == static_cast<int>(i) ? n++ : number[size_t(first[i])];
  Mesh out;
  out.vertices = distinct_positions(m.vertices, first);
  out.triangles.resize(3, m.triangles.cols());
  for (Eigen::Index k = 0; k < m.triangles.size(); ++k)
    out.triangles.data()[k] = number[size_t(m.triangles.data()[k])];
  return out;
}

long boundary_edges(const Mesh& m) {
  return boundary_edges(m, first_at_same_position(m.vertices));
}

long boundary_edges(const Mesh& m, const std::vector<int>& first) {
  // Each welded edge (u < v) filed under u, counting sort style; then each
  // vertex's few edges are sorted alone (one sort of all edges was most of
  // this function on a fine part).
  const size_t n = first.size();
  std::vector<int> start(n + 1, 0);
  auto each_edge = [&](auto&& visit) {
    for (Eigen::Index t = 0; t < m.triangles.cols(); ++t)
      for (int k = 0; k < 3; ++k) {
        const int u = first[m.triangles(k, t)], v = first[m.triangles((k + 1) % 3, t)];
        if (u != v) visit(std::min(u, v), std::max(u, v));
      }
  };
  each_edge([&](int u, int) { ++start[size_t(u) + 1]; });
  for (size_t i = 0; i < n; ++i) start[i + 1] += start[i];
  std::vector<int> other(static_cast<size_t>(start[n]));
  std::vector<int> fill(start.begin(), start.end() - 1);
  each_edge([&](int u, int v) { other[size_t(fill[size_t(u)]++)] = v; });
  long odd = 0;
  for (size_t u = 0; u < n; ++u) {
    const auto b = other.begin() + start[u], e = other.begin() + start[u + 1];
    std::sort(b, e);
    for (auto k = b; k != e;) {
      auto end = k;
      while (end != e && *end == *k) ++end;
      odd += (end - k) % 2;
      k = end;
    }
  }
  return odd;
}

}  // namespace pd
