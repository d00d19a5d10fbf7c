// The sag cache (scene/sag_cache.h): a measurement reads back bit for bit,
// features and patches; keys follow the content and the per-mesh reading; an
// entry that does not read back whole is measured again (a miss).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "scene/sag_cache.h"

using namespace pd;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d =
      fs::path(testing::TempDir()) / ("sag_cache_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  return d;
}

Aabb box(const Vec3& lo, const Vec3& hi) {
  Aabb b;
  b.lo = lo;
  b.hi = hi;
  return b;
}

TessellationSag measured() {
  TessellationSag s;
  s.resolution = std::ldexp(1.0, -20);
  s.concave = 1.0 / 3.0;
  s.convex = 0.1;
  s.creases = 42;
  s.design_edges = 12;
  SagFeature f;
  f.box = box(Vec3(-1e5, 0.1, -0.0), Vec3(1e5 + 0.3, 2.0 / 3.0, 7));
  f.concave = 1.0 / 3.0;
  f.convex = std::nextafter(0.1, 1.0);
  f.radius = 12.5;
  f.segments = 64;
  f.facets = 128;
  f.patches = {{box(Vec3(0, 0, 0), Vec3(1, 1, 1)), 0.01, 0.02},
               {box(Vec3(1, 0, 0), Vec3(2, 1, 1)), 1e-300, 0.0}};
  s.features = {f, SagFeature{}};
  return s;
}

}  // namespace

TEST(SagCache, AMeasurementReadsBackBitForBit) {
  const fs::path dir = fresh_dir("roundtrip");
  const std::string k = sag_key("aaaa", false);
  EXPECT_EQ(k, sag_key("aaaa", false));
  EXPECT_NE(k, sag_key("aaab", false));  // another file's bytes
  EXPECT_NE(k, sag_key("aaaa", true));   // read mesh by mesh
  const TessellationSag s = measured();
  ASSERT_EQ(write_cached_sag(dir.string(), k, s), "");
  const auto back = read_cached_sag(dir.string(), k);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->resolution, s.resolution);
  EXPECT_EQ(back->concave, s.concave);
  EXPECT_EQ(back->convex, s.convex);
  EXPECT_EQ(back->creases, s.creases);
  EXPECT_EQ(back->design_edges, s.design_edges);
  ASSERT_EQ(back->features.size(), s.features.size());
  for (size_t i = 0; i < s.features.size(); ++i) {
    const SagFeature &f = back->features[i], &w = s.features[i];
    SCOPED_TRACE(i);
    EXPECT_EQ(f.box.lo, w.box.lo);
    EXPECT_EQ(f.box.hi, w.box.hi);
    EXPECT_EQ(f.concave, w.concave);
    EXPECT_EQ(f.convex, w.convex);
    EXPECT_EQ(f.radius, w.radius);
    EXPECT_EQ(f.segments, w.segments);
    EXPECT_EQ(f.facets, w.facets);
    ASSERT_EQ(f.patches.size(), w.patches.size());
    for (size_t q = 0; q < w.patches.size(); ++q) {
      EXPECT_EQ(f.patches[q].box.lo, w.patches[q].box.lo);
      EXPECT_EQ(f.patches[q].box.hi, w.patches[q].box.hi);
      EXPECT_EQ(f.patches[q].concave, w.patches[q].concave);
      EXPECT_EQ(f.patches[q].convex, w.patches[q].convex);
    }
  }
  EXPECT_FALSE(read_cached_sag(dir.string(), sag_key("aaaa", true)));  // not stored
  fs::remove_all(dir);
}

TEST(SagCache, ADamagedEntryIsMeasuredAgain) {
  const fs::path dir = fresh_dir("damaged");
  const std::string k = sag_key("bbbb", false);
  ASSERT_EQ(write_cached_sag(dir.string(), k, measured()), "");
  ASSERT_TRUE(read_cached_sag(dir.string(), k));
  const fs::path file = dir / (k + ".pds");
  ASSERT_TRUE(fs::exists(file));
  fs::resize_file(file, fs::file_size(file) - 2);
  EXPECT_FALSE(read_cached_sag(dir.string(), k));
  fs::remove_all(dir);
}
