// Memory for loader processes (memory_limit.cpp): half of what is available,
// split evenly, and nothing when it is unknown.
#include <gtest/gtest.h>

#include <cmath>

#include "memory_limit.h"

using namespace pd;

TEST(MemoryLimit, HalfTheAvailableMemorySplitEvenly) {
  EXPECT_EQ(memory_share_mb(8000, 1), 4000);
  EXPECT_EQ(memory_share_mb(8000, 4), 1000);
  EXPECT_EQ(memory_share_mb(8000, 0), 4000);  // no process count: as one
  EXPECT_EQ(memory_share_mb(0, 4), 0);        // unknown: no cap
  EXPECT_EQ(memory_share_mb(-1, 4), 0);
  EXPECT_EQ(memory_share_mb(std::nan(""), 4), 0);
}

TEST(MemoryLimit, TheMachineHasSomeMemory) {
  const double mb = available_memory_mb();
  EXPECT_GT(mb, 16.0);                        // this test runs somewhere
  EXPECT_LT(mb, 1e9);                         // below a petabyte
  EXPECT_FALSE(cap_address_space_growth(0));  // nothing asked: nothing changed
}
