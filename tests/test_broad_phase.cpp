// The broad phase (broad_phase.cpp): the candidate pairs of a set of boxes.
#include <gtest/gtest.h>

#include "batch/broad_phase.h"
#include "corpus/generators.h"

using namespace pd;

TEST(BroadPhase, MatchesBruteForce) {
  SphereSampler r(7);
  std::vector<Aabb> boxes;
  for (int k = 0; k < 400; ++k) {
    const Vec3 c(100 * r.uniform(), 100 * r.uniform(), 100 * r.uniform());
    const Vec3 h(5 * r.uniform(), 5 * r.uniform(), 5 * r.uniform());
    boxes.push_back({c - h, c + h});
  }
  boxes.push_back({boxes[0].hi, boxes[0].hi + Vec3::Ones()});  // touching a corner counts
  std::vector<std::pair<int, int>> brute;
  for (int i = 0; i < int(boxes.size()); ++i)
    for (int j = i + 1; j < int(boxes.size()); ++j)
      if (boxes[i].overlaps(boxes[j])) brute.emplace_back(i, j);
  EXPECT_EQ(overlapping_boxes(boxes, 0.0), brute);
}
