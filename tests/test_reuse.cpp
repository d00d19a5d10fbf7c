// A pair's old result taken again (reuse.cpp): only under the same settings,
// with both parts unchanged, and never an error.
#include <gtest/gtest.h>

#include "batch/reuse.h"
#include "results/fingerprint.h"

using namespace pd;

namespace {

PriorResults prior_of() {
  PriorResults p;
  p.settings_hash = "s1";
  p.part_hash = {{"frame", "hf"}, {"lid", "hl"}, {"pin", "hp"}};
  PairResult lid;
  lid.status = Status::kInterference;
  lid.depth = 1.5;
  lid.method = "mlsl";
  p.pairs[pair_fingerprint("frame", "lid")] = lid;
  PairResult pin;
  pin.status = Status::kError;
  pin.error = "worker crashed";
  p.pairs[pair_fingerprint("frame", "pin")] = pin;
  return p;
}

}  // namespace

TEST(Reuse, TheSamePairUnderTheSameSettingsIsReused) {
  const PriorResults p = prior_of();
  const auto r = prior_result(p, "s1", 4, "frame", "hf", 7, "lid", "hl");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->a, 4);  // this run's indices
  EXPECT_EQ(r->b, 7);
  EXPECT_TRUE(r->reused);
  EXPECT_EQ(r->status, Status::kInterference);
  EXPECT_EQ(r->depth, 1.5);
  EXPECT_EQ(r->method, "mlsl");
  // The fingerprint does not depend on which part is a.
  EXPECT_TRUE(prior_result(p, "s1", 0, "lid", "hl", 1, "frame", "hf"));
}

TEST(Reuse, AnythingChangedIsSolvedAgain) {
  const PriorResults p = prior_of();
  EXPECT_FALSE(prior_result(p, "s2", 0, "frame", "hf", 1, "lid", "hl"));   // other settings
  EXPECT_FALSE(prior_result(p, "s1", 0, "frame", "hf", 1, "lid", "hX"));   // lid changed
  EXPECT_FALSE(prior_result(p, "s1", 0, "frame", "hX", 1, "lid", "hl"));   // frame changed
  EXPECT_FALSE(prior_result(p, "s1", 0, "frame", "hf", 1, "bolt", "hb"));  // a new part
  EXPECT_FALSE(prior_result(p, "s1", 0, "lid", "hl", 1, "pin", "hp"));     // never solved together
  EXPECT_FALSE(prior_result(p, "s1", 0, "frame", "hf", 1, "pin", "hp"));   // an error: tried again
}
