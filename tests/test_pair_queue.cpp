// The refinement's pair queue (batch/pair_queue.h): the locality order, a
// little reordered so that no thread waits for a part another is fetching.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "batch/pair_queue.h"

using pd::PairQueue;

TEST(PairQueue, OneThreadTakesThePairsInOrder) {
  PairQueue q({{0, 1}, {0, 2}, {3, 4}, {0, 5}}, 16);
  for (size_t k = 0; k < 4; ++k) {
    const auto taken = q.take();
    ASSERT_TRUE(taken);
    EXPECT_EQ(*taken, k);
    q.fetched(k);
  }
  EXPECT_FALSE(q.take());
}

TEST(PairQueue, ASecondThreadSkipsAPartBeingFetched) {
  // A ring (part 0) with its balls, then a shaft and its pin elsewhere.
  PairQueue q({{0, 1}, {0, 2}, {0, 3}, {5, 6}, {0, 4}, {6, 7}}, 16);
  EXPECT_EQ(q.take(), 0u);  // the first thread builds the ring
  EXPECT_EQ(q.take(), 3u);  // the second goes past the ring's other pairs
  EXPECT_EQ(q.take(), 1u);  // nothing free left: the first open pair, waited for
  q.fetched(0);
  q.fetched(1);
  EXPECT_EQ(q.take(), 2u);  // the ring in hand: its pairs in order again
  EXPECT_EQ(q.take(), 4u);  // part 6 is still being fetched for pair 3
  q.fetched(3);
  EXPECT_EQ(q.take(), 5u);
  EXPECT_FALSE(q.take());
}

TEST(PairQueue, LooksOnlySoFarAhead) {
  PairQueue q({{0, 1}, {0, 2}, {0, 3}, {0, 4}, {5, 6}}, 2);
  EXPECT_EQ(q.take(), 0u);
  // Pairs 1 to 3 are within the look-ahead and all wait for part 0; pair 4 is
  // beyond it: the first open pair is taken.
  EXPECT_EQ(q.take(), 1u);
}

TEST(PairQueue, EveryPairIsTakenOnceWhateverTheThreads) {
  std::vector<std::pair<int, int>> pairs;
  for (int k = 0; k < 2000; ++k) pairs.push_back({k % 7, 7 + k % 13});
  PairQueue q(pairs, 16);
  std::vector<std::atomic<int>> times(pairs.size());
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&] {
      while (const auto k = q.take()) {
        ++times[*k];
        q.fetched(*k);
      }
    });
  for (auto& t : threads) t.join();
  for (size_t k = 0; k < pairs.size(); ++k) EXPECT_EQ(times[k].load(), 1) << k;
}
