// The names of node parts (node_names.cpp): escaped, numbered and joined into
// ids and groups.
#include <gtest/gtest.h>

#include "scene/node_names.h"

TEST(NodeNames, EscapedNumberedAndJoined) {
  EXPECT_EQ(pd::escape_node_name("a/b%c#d"), "a%2Fb%25c%23d");
  EXPECT_EQ(pd::sibling_segments({"bolt", "", "bolt", "nut", "bolt", "node1", "bolt#2"}),
            (std::vector<std::string>{"bolt", "node1", "bolt#2", "nut", "bolt#3", "node1#2",
                                      "bolt%232"}));
  EXPECT_EQ(pd::node_part_id("asm", "frame/bolt"), "asm/frame/bolt");
  EXPECT_EQ(pd::node_part_group("", "bolt"), "");
  EXPECT_EQ(pd::node_part_group("", "frame/sub/bolt"), "frame/sub");
  EXPECT_EQ(pd::node_part_group("wing", "bolt"), "wing");
  EXPECT_EQ(pd::node_part_group("wing/rib", "frame/bolt"), "wing/rib/frame");
}
