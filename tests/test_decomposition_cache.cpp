// The decomposition cache (decomposition_cache.cpp): entries read back, damage is a miss.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "batch/decomposition_cache.h"
#include "scratch_dir.h"

using namespace pd;
namespace fs = std::filesystem;

namespace {}  // namespace

TEST(DecompositionCache, EntriesReadBackAndDamageIsIgnored) {
  const fs::path dir = pd_test::scratch_dir("decomposition_cache", "decomposition");
  StoredDecomposition d;
  Points a(3, 4), b(3, 5);
  a.setRandom();
  b.setRandom();
  d.pieces = {a, b};
  d.complete = false;
  d.note = "time box\nran out";
  d.seconds = 1.0 / 3.0;
  ASSERT_EQ(write_cached_decomposition(dir.string(), "k", d), "");
  const auto back = read_cached_decomposition(dir.string(), "k");
  ASSERT_TRUE(back);
  ASSERT_EQ(back->pieces.size(), 2u);
  EXPECT_EQ(back->pieces[0], a);
  EXPECT_EQ(back->pieces[1], b);
  EXPECT_FALSE(back->complete);
  EXPECT_EQ(back->note, "time box ran out");
  EXPECT_EQ(back->seconds, d.seconds);
  const fs::path file = dir / "k.pdd";
  fs::resize_file(file, fs::file_size(file) - 8);
  EXPECT_FALSE(read_cached_decomposition(dir.string(), "k"));
  fs::remove_all(dir);
}
