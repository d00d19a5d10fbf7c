// How many workers the open-file limit allows (worker_limit.cpp).
#include <gtest/gtest.h>
#include <sys/resource.h>

#include "worker_limit.h"

using namespace pd;

TEST(WorkerLimit, FewerWorkersUnderALowLimitAndItSaysWhy) {
  rlimit saved{};
  ASSERT_EQ(getrlimit(RLIMIT_NOFILE, &saved), 0);
  std::string why;
  EXPECT_EQ(workers_within_fd_limit(1, why), 1);
  EXPECT_EQ(why, "");
  // A soft limit of 64 descriptors: 1000 workers need more. The limit is
  // raised toward the hard one when it allows; else fewer workers, saying why.
  if (saved.rlim_cur >= 64) {
    rlimit low{64, saved.rlim_max};
    ASSERT_EQ(setrlimit(RLIMIT_NOFILE, &low), 0);
    const int n = workers_within_fd_limit(1000, why);
    rlimit now{};
    ASSERT_EQ(getrlimit(RLIMIT_NOFILE, &now), 0);
    if (saved.rlim_max == RLIM_INFINITY || saved.rlim_max >= 8192) {
      EXPECT_EQ(n, 1000) << why;
      EXPECT_GT(now.rlim_cur, 2000u);  // raised: two pipe ends per worker at least
    } else {
      EXPECT_GE(n, 1);
      EXPECT_LT(n, 1000);
      EXPECT_NE(why, "");
    }
    ASSERT_EQ(setrlimit(RLIMIT_NOFILE, &saved), 0);
  }
}
