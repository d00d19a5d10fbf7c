// The batch run (batch/run.h) in-process: a worker's answer read back into its
// pair's result, an unreadable one an error on that pair only (issue 11).
#include <gtest/gtest.h>

#include "awkward_doubles.h"
#include "batch/run.h"
#include "results/codec.h"

using pd::PairResult;

TEST(PairResultCodec, AnUnreadableWorkerAnswerIsAnErrorOnItsPairOnly) {
  const PairResult good = pd::pair_result_from_worker(
      true, pd::encode_pair_result(pd_test::with_every_double(2.0)), 3, 7, "mlsl");
  EXPECT_EQ(good.status, pd::Status::kInterference);
  EXPECT_EQ(good.depth, 2.0);
  for (const std::string& payload :
       {std::string(), std::string("{\"d\": null}"), std::string("\x85garbage")}) {
    const PairResult r = pd::pair_result_from_worker(true, payload, 4, 9, "exact");
    EXPECT_EQ(r.status, pd::Status::kError);
    EXPECT_EQ(r.a, 4);
    EXPECT_EQ(r.b, 9);
    EXPECT_EQ(r.method, "exact");
    EXPECT_NE(r.error.find("worker result unreadable"), std::string::npos) << r.error;
  }
  const PairResult crashed = pd::pair_result_from_worker(false, "worker crashed", 1, 2, "mlsl");
  EXPECT_EQ(crashed.status, pd::Status::kError);
  EXPECT_EQ(crashed.error, "worker crashed");
}
