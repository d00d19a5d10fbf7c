// The convexity cache (convexity_cache.cpp): entries read back exactly, keys follow their inputs.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "scene/convexity_cache.h"
#include "scratch_dir.h"

using namespace pd;
namespace fs = std::filesystem;

namespace {}  // namespace

TEST(ConvexityCache, EntriesReadBackExactlyAndKeysFollowTheirInputs) {
  const fs::path dir = pd_test::scratch_dir("convexity_cache", "convexity");
  const std::string k = convexity_key("aaaa", 0.01, 0.02);
  EXPECT_EQ(k, convexity_key("aaaa", 0.01, 0.02));
  EXPECT_NE(k, convexity_key("aaab", 0.01, 0.02));                       // another file's bytes
  EXPECT_NE(k, convexity_key("aaaa", std::nextafter(0.01, 1.0), 0.02));  // another tolerance
  EXPECT_NE(k, convexity_key("aaaa", 0.01, std::nextafter(0.02, 1.0)));  // another threshold
  const StoredConvexity c{1.0 / 3.0, true};
  ASSERT_EQ(write_cached_convexity(dir.string(), k, c), "");
  const auto back = read_cached_convexity(dir.string(), k);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->concavity, c.concavity);  // exact bits
  EXPECT_TRUE(back->closed);
  EXPECT_FALSE(read_cached_convexity(dir.string(), convexity_key("aaaa", 0.01, 0.03)));
  const fs::path file = dir / (k + ".pdv");
  fs::resize_file(file, fs::file_size(file) - 1);
  EXPECT_FALSE(read_cached_convexity(dir.string(), k));
  fs::remove_all(dir);
}
