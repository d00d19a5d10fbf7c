// The exit codes and the rule that orders them (exit_code.h).
#include <gtest/gtest.h>

#include "exit_code.h"

using namespace pd;

// The documented values (README, docs/ci.md): scripts test them by number.
static_assert(kExitClean == 0 && kExitFinding == 1 && kExitBadInput == 2 && kExitIncomplete == 3);

TEST(ExitCode, IncompleteWinsThenFailing) {
  EXPECT_EQ(run_exit_code(false, false), kExitClean);
  EXPECT_EQ(run_exit_code(false, true), kExitFinding);
  EXPECT_EQ(run_exit_code(true, false), kExitIncomplete);
  EXPECT_EQ(run_exit_code(true, true), kExitIncomplete);
  static_assert(run_exit_code(true, true) == 3, "usable in constant expressions");
}
