// Disjoint sets over 0..n−1 (union-find with path halving). Each set's root
// is its smallest member, whatever the order of the joins, so whatever is
// built from the roots (feature ids, group order) stays deterministic.
#pragma once

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace pd {

class UnionFind {
 public:
  explicit UnionFind(size_t n) : up_(n) { std::iota(up_.begin(), up_.end(), size_t(0)); }
  /// The root of x's set: its smallest member.
  size_t find(size_t x) {
    while (up_[x] != x) x = up_[x] = up_[up_[x]];
    return x;
  }
  void join(size_t x, size_t y) {
    x = find(x), y = find(y);
    if (x != y) up_[std::max(x, y)] = std::min(x, y);
  }

 private:
  std::vector<size_t> up_;
};

}  // namespace pd
