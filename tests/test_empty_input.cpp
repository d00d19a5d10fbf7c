// A run that checked nothing (empty_input.cpp): every part failed, said once
// with the count; not when some part was usable or there is none.
#include <gtest/gtest.h>

#include "batch/empty_input.h"

using namespace pd;

TEST(EmptyInput, EveryPartFailedSaysHowMany) {
  RunResult run;
  EXPECT_FALSE(every_part_failed(run));  // no part: the scene's own problem
  for (const char* id : {"a", "b", "c"}) {
    Part p;
    p.id = id;
    p.error = "unreadable";
    run.parts.push_back(p);
  }
  const auto why = every_part_failed(run);
  ASSERT_TRUE(why);
  EXPECT_EQ(why->rfind("every part failed (3 of 3, ", 0), 0u) << *why;
  EXPECT_NE(why->find("--allow-empty"), std::string::npos) << *why;
  run.parts[1].error.reset();  // one usable part: the run checked what it could
  EXPECT_FALSE(every_part_failed(run));
}
