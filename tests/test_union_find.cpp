#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "geometry/union_find.h"

TEST(UnionFind, RootsAreTheSmallestMembersWhateverTheOrderOfJoins) {
  // Chains 0-3-6-9 and 1-4-7, joined in shuffled orders: the same sets, rooted
  // at 0 and 1; 2, 5 and 8 stay alone.
  std::vector<std::pair<size_t, size_t>> joins{{9, 6}, {3, 6}, {0, 3}, {7, 4}, {4, 1}};
  std::mt19937 rng(3);
  for (int trial = 0; trial < 20; ++trial) {
    std::shuffle(joins.begin(), joins.end(), rng);
    pd::UnionFind uf(10);
    for (const auto& [x, y] : joins) uf.join(x, y);
    for (size_t k : {0, 3, 6, 9}) EXPECT_EQ(uf.find(k), 0u) << "trial " << trial;
    for (size_t k : {1, 4, 7}) EXPECT_EQ(uf.find(k), 1u) << "trial " << trial;
    for (size_t k : {2, 5, 8}) EXPECT_EQ(uf.find(k), k);
  }
}
