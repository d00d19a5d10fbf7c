// The node names cache (scene/node_names_cache.h): a split file's node paths
// read back byte for byte, any byte in a name; keys follow the file's content;
// an entry that does not read back whole is a miss.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "scene/node_names_cache.h"
#include "scratch_dir.h"

using namespace pd;
namespace fs = std::filesystem;

namespace {}  // namespace

TEST(NodeNamesCache, PathsReadBackByteForByte) {
  const fs::path dir = pd_test::absent_dir("node_names", "roundtrip");
  const std::string k = node_names_key("aaaa");
  EXPECT_EQ(k, node_names_key("aaaa"));
  EXPECT_NE(k, node_names_key("aaab"));
  const std::vector<std::string> names = {"root/arm", "root/arm 2\nwith a line end",
                                          std::string("nul\0inside", 10), "", "root/ü"};
  ASSERT_EQ(write_cached_node_names(dir.string(), k, names), "");
  const auto back = read_cached_node_names(dir.string(), k);
  ASSERT_TRUE(back);
  EXPECT_EQ(*back, names);
  EXPECT_FALSE(read_cached_node_names(dir.string(), node_names_key("aaab")));  // not stored
  fs::remove_all(dir);
}

TEST(NodeNamesCache, ADamagedEntryIsAMiss) {
  const fs::path dir = pd_test::absent_dir("node_names", "damaged");
  const std::string k = node_names_key("bbbb");
  ASSERT_EQ(write_cached_node_names(dir.string(), k, {"a", "b/c"}), "");
  ASSERT_TRUE(read_cached_node_names(dir.string(), k));
  const fs::path file = dir / (k + ".pdn");
  ASSERT_TRUE(fs::exists(file));
  fs::resize_file(file, fs::file_size(file) - 1);
  EXPECT_FALSE(read_cached_node_names(dir.string(), k));
  fs::remove_all(dir);
}
