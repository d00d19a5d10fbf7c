// The parallel loop (parallel_for.h): every index once, whatever the threads,
// and the exception a serial loop would have thrown.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include "parallel_for.h"

using namespace pd;

TEST(ParallelFor, EveryIndexOnceOnAnyThreads) {
  for (const int threads : {0, 1, 2, 7}) {
    for (const size_t n : {size_t(0), size_t(1), size_t(2), size_t(100)}) {
      std::vector<std::atomic<int>> calls(n);
      parallel_for(n, threads, [&](size_t k) { ++calls[k]; });
      for (size_t k = 0; k < n; ++k) EXPECT_EQ(calls[k], 1) << threads << " threads, " << k;
    }
  }
}

TEST(ParallelFor, OneThreadRunsInTheCaller) {
  const std::thread::id me = std::this_thread::get_id();
  bool all_here = true;
  parallel_for(5, 1, [&](size_t) { all_here = all_here && std::this_thread::get_id() == me; });
  EXPECT_TRUE(all_here);
}

TEST(ParallelFor, TheLowestFailingIndexIsRethrownAfterAllEnded) {
  std::atomic<int> ran{0};
  try {
    parallel_for(50, 4, [&](size_t k) {
      ++ran;
      if (k == 7 || k == 30) throw std::runtime_error("item " + std::to_string(k));
    });
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "item 7");
  }
  EXPECT_EQ(ran, 50);  // the others still ran: no item is lost to another's failure
}
