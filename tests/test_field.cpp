// A field's description (field.h): its builders set one attribute each and
// keep the others.
#include <gtest/gtest.h>

#include <cstring>

#include "results/field.h"

using namespace pd;

TEST(Field, BuildersComposeAndKeepTheOthers) {
  constexpr Field plain{"depth"};
  static_assert(plain.shown && !plain.omit_empty && !plain.echo && plain.group == nullptr);
  constexpr Field f = Field{"distance"}.in("clearance").when(true).unless_empty().echoing();
  static_assert(f.shown && f.omit_empty && f.echo);
  EXPECT_STREQ(f.key, "distance");
  EXPECT_STREQ(f.group, "clearance");
  // `when` only ever hides: a hidden field stays hidden.
  static_assert(!Field{"x"}.when(false).when(true).shown);
  static_assert(!Field{"x"}.when(true).when(false).shown);
  constexpr Field g = Field{"error"}.when(false).in("a");
  EXPECT_FALSE(g.shown);
  EXPECT_STREQ(g.group, "a");
  EXPECT_STREQ(g.key, "error");
}
