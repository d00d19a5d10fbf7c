// Globs of the rules (rule_glob.cpp): ids and group paths.
#include <gtest/gtest.h>

#include "scene/rule_glob.h"

TEST(RuleGlob, IdsAndGroups) {
  EXPECT_TRUE(pd::glob_match("bolt-*", "bolt-12"));
  EXPECT_TRUE(pd::glob_match("*/nut?", "asm/rib/nut7"));  // ids: `*` crosses '/'
  EXPECT_FALSE(pd::glob_match("bolt-?", "bolt-12"));
  EXPECT_FALSE(pd::glob_match("bolt", "bolt-1"));
  EXPECT_TRUE(pd::glob_match("*a*b*c", "xxaxbxxc"));
  // Groups: a pattern matching leading segments selects everything under them.
  EXPECT_TRUE(pd::group_glob_match("wing", "wing/rib-7/bracket"));
  EXPECT_TRUE(pd::group_glob_match("wing/rib-*", "wing/rib-7/bracket"));
  EXPECT_FALSE(pd::group_glob_match("wing/rib-*", "wing"));
  EXPECT_FALSE(pd::group_glob_match("wing*7", "wing/rib-7"));  // `*` never crosses '/'
  EXPECT_TRUE(pd::group_glob_match("wing*", "wing/rib-7"));    // "wing" and what is under it
  EXPECT_TRUE(pd::group_glob_match("wing*", "wings/rib-7"));
  EXPECT_TRUE(pd::group_glob_match("**/bracket", "wing/rib-7/bracket"));
  EXPECT_FALSE(pd::group_glob_match("**/bracket", "wing/rib-7/bolt"));
  EXPECT_FALSE(pd::group_glob_match("wing", ""));  // a part without a group is in none
  EXPECT_FALSE(pd::group_glob_match("rib-7", "wing/rib-7"));
}
