// The hull cache (scene/hull_cache.h): entries read back exactly or not at all;
// a rerun takes a file's hulls from it, and under pieces "hull" does not read
// the file at all, while pieces "auto" still reads the surface it keeps; under
// tolerance auto the entry holds the file's sag too (features and patches bit
// for bit), added by the first auto run; large inline parts take theirs from
// it by list and placement.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "cache_file.h"
#include "file_hash.h"
#include "scene/hull_cache.h"
#include "scene/parts.h"
#include "scene/scene.h"
#include "scratch_dir.h"
#include "tolerances.h"

using namespace pd;
namespace fs = std::filesystem;

namespace {

const std::string kBox = std::string(PDCHECK_SOURCE_DIR) + "/testdata/formats/box.obj";

// Two instances of the box mesh under `pieces`, 10 apart.
SceneSpec box_scene(const std::string& pieces, const std::string& tolerance = "0.1") {
  const std::string part = R"({"mesh": ")" + kBox + R"(", "pieces": ")" + pieces + R"(")";
  return parse_scene_json(
      R"({"tolerance": )" + tolerance + R"(, "parts": [)" + part + R"(, "id": "a"}, )" + part +
          R"(, "id": "b", "transform": [1,0,0,10, 0,1,0,0, 0,0,1,0, 0,0,0,1]}]})",
      "s.json", "");
}

std::vector<fs::path> entries(const fs::path& dir, const std::string& ext) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.path().extension() == ext) out.push_back(e.path());
  return out;
}

std::vector<fs::path> all_entries(const fs::path& dir) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) out.push_back(e.path());
  return out;
}

Aabb aabb(const Vec3& lo, const Vec3& hi) {
  Aabb b;
  b.lo = lo;
  b.hi = hi;
  return b;
}

// A measurement with awkward values: exact thirds, a negative zero, a
// subnormal-adjacent 1e-300, two features (one empty).
TessellationSag measured() {
  TessellationSag s;
  s.resolution = std::ldexp(1.0, -20);
  s.concave = 1.0 / 3.0;
  s.convex = 0.1;
  s.creases = 42;
  s.design_edges = 12;
  SagFeature f;
  f.box = aabb(Vec3(-1e5, 0.1, -0.0), Vec3(1e5 + 0.3, 2.0 / 3.0, 7));
  f.concave = 1.0 / 3.0;
  f.convex = std::nextafter(0.1, 1.0);
  f.radius = 12.5;
  f.segments = 64;
  f.facets = 128;
  f.patches = {{aabb(Vec3(0, 0, 0), Vec3(1, 1, 1)), 0.01, 0.02},
               {aabb(Vec3(1, 0, 0), Vec3(2, 1, 1)), 1e-300, 0.0}};
  s.features = {f, SagFeature{}};
  return s;
}

StoredHulls hulls_with(std::optional<TessellationSag> sag) {
  StoredHulls h;
  h.counts = {8, 12};
  h.reduced.push_back(Points::Random(3, 5));
  h.reduced.push_back(Points::Random(3, 7));
  h.warnings = {"a warning"};
  h.sag = std::move(sag);
  return h;
}

// A loader that crashes on the box file: a part that reads it fails.
void crash_on_box(const std::string& path) {
  if (path.size() >= 7 && path.compare(path.size() - 7, 7, "box.obj") == 0) std::abort();
}

}  // namespace

TEST(HullCache, EntriesReadBackExactlyOrNotAtAll) {
  const fs::path dir = pd_test::absent_dir("hull_cache", "entries");
  StoredHulls h;
  h.counts = {8, 12};
  h.reduced.push_back(Points::Random(3, 5));
  h.reduced.push_back(Points::Random(3, 7));
  const std::string key = hulls_key("abc", false);
  EXPECT_NE(key, hulls_key("abc", true));
  EXPECT_NE(key, hulls_key("abd", false));
  ASSERT_EQ(write_cached_hulls(dir.string(), key, h), "");
  const auto back = read_cached_hulls(dir.string(), key);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->counts, h.counts);
  ASSERT_EQ(back->reduced.size(), 2u);
  EXPECT_EQ(back->reduced[0], h.reduced[0]);  // bit for bit
  EXPECT_EQ(back->reduced[1], h.reduced[1]);
  EXPECT_FALSE(read_cached_hulls(dir.string(), hulls_key("abc", true)));
  // Cut short: a miss, not an error.
  const auto files = entries(dir, ".pdh");
  ASSERT_EQ(files.size(), 1u);
  fs::resize_file(files[0], fs::file_size(files[0]) - 9);
  EXPECT_FALSE(read_cached_hulls(dir.string(), key));
}

TEST(HullCache, ASagReadsBackBitForBit) {
  const fs::path dir = pd_test::absent_dir("hull_cache", "sag");
  const std::string k = hulls_key("aaaa", false);
  const StoredHulls h = hulls_with(measured());
  ASSERT_EQ(write_cached_hulls(dir.string(), k, h), "");
  const auto entry = read_cached_hulls(dir.string(), k);
  ASSERT_TRUE(entry);
  EXPECT_EQ(entry->counts, h.counts);
  ASSERT_EQ(entry->reduced.size(), 2u);
  EXPECT_EQ(entry->reduced[0], h.reduced[0]);
  EXPECT_EQ(entry->reduced[1], h.reduced[1]);
  EXPECT_EQ(entry->warnings, h.warnings);
  ASSERT_TRUE(entry->sag);
  const TessellationSag &back = *entry->sag, &s = *h.sag;
  EXPECT_EQ(back.resolution, s.resolution);
  EXPECT_EQ(back.concave, s.concave);
  EXPECT_EQ(back.convex, s.convex);
  EXPECT_EQ(back.creases, s.creases);
  EXPECT_EQ(back.design_edges, s.design_edges);
  ASSERT_EQ(back.features.size(), s.features.size());
  for (size_t i = 0; i < s.features.size(); ++i) {
    const SagFeature &f = back.features[i], &w = s.features[i];
    SCOPED_TRACE(i);
    EXPECT_EQ(f.box.lo, w.box.lo);
    EXPECT_EQ(f.box.hi, w.box.hi);
    EXPECT_TRUE(std::signbit(f.box.lo.z()) == std::signbit(w.box.lo.z()));
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
  // An entry without a sag reads back without one.
  ASSERT_EQ(write_cached_hulls(dir.string(), k, hulls_with(std::nullopt)), "");
  const auto plain = read_cached_hulls(dir.string(), k);
  ASSERT_TRUE(plain);
  EXPECT_FALSE(plain->sag);
  EXPECT_EQ(plain->counts, h.counts);
  fs::remove_all(dir);
}

TEST(HullCache, AnEntryWithADamagedSagIsAMiss) {
  const fs::path dir = pd_test::absent_dir("hull_cache", "damaged_sag");
  const std::string k = hulls_key("bbbb", false);
  ASSERT_EQ(write_cached_hulls(dir.string(), k, hulls_with(measured())), "");
  ASSERT_TRUE(read_cached_hulls(dir.string(), k));
  const fs::path file = dir / (k + ".pdh");
  ASSERT_TRUE(fs::exists(file));
  // The sag's feature count made huge, the checksum kept right: the entry's
  // own parse refuses it.
  const CacheKind kind{"pdcheck-hulls-4", ".pdh"};
  std::string body = *read_cache_entry(dir.string(), kind, k);
  const size_t sag_at = body.find("a warning\n") + 10;  // resolution, concave, convex, creases,
  const long huge = 1L << 40;                           // design_edges, then the count
  body.replace(sag_at + 5 * 8, sizeof huge, reinterpret_cast<const char*>(&huge), sizeof huge);
  ASSERT_EQ(write_cache_entry(dir.string(), kind, k, body), "");
  ASSERT_TRUE(read_cache_entry(dir.string(), kind, k));
  EXPECT_FALSE(read_cached_hulls(dir.string(), k));
  // A non-finite sag is refused too.
  ASSERT_EQ(write_cached_hulls(dir.string(), k, hulls_with(measured())), "");
  body = *read_cache_entry(dir.string(), kind, k);
  const double nan = NAN;
  body.replace(sag_at + 8, sizeof nan, reinterpret_cast<const char*>(&nan), sizeof nan);
  ASSERT_EQ(write_cache_entry(dir.string(), kind, k, body), "");
  EXPECT_FALSE(read_cached_hulls(dir.string(), k));
  // Cut short: the checksum fails.
  ASSERT_EQ(write_cached_hulls(dir.string(), k, hulls_with(measured())), "");
  fs::resize_file(file, fs::file_size(file) - 2);
  EXPECT_FALSE(read_cached_hulls(dir.string(), k));
  fs::remove_all(dir);
}

TEST(HullCache, UnderAutoOneEntryHoldsTheHullsAndTheSag) {
  const fs::path dir = pd_test::absent_dir("hull_cache", "auto");
  const PartsCache cache{dir.string()};
  // A run without auto stores the hulls alone.
  ASSERT_FALSE(build_parts(box_scene("hull"), 1, {}, kDefaultLoadTimeout, cache)[0].error);
  const std::string key = hulls_key(file_content_hash(kBox), false);
  ASSERT_TRUE(read_cached_hulls(dir.string(), key));
  EXPECT_FALSE(read_cached_hulls(dir.string(), key)->sag);
  // Under auto the entry has no sag yet: the file is read to measure it.
  const SceneSpec s = box_scene("hull", R"("auto")");
  EXPECT_TRUE(
      build_parts(s, 1, {}, kDefaultLoadTimeout, cache, kAutoLoadMemory, crash_on_box)[0].error);
  const auto cold = build_parts(s, 1, {}, kDefaultLoadTimeout, cache);
  ASSERT_FALSE(cold[0].error) << *cold[0].error;
  ASSERT_TRUE(cold[0].sag);
  // It is stored in the file's one entry, and a rerun reads neither the file
  // nor any other entry.
  EXPECT_EQ(all_entries(dir), std::vector<fs::path>{dir / (key + ".pdh")});
  const auto entry = read_cached_hulls(dir.string(), key);
  ASSERT_TRUE(entry);
  ASSERT_TRUE(entry->sag);
  EXPECT_EQ(entry->sag->design_edges, 12);  // the box: no sag, 12 sharp edges
  const auto warm =
      build_parts(s, 1, {}, kDefaultLoadTimeout, cache, kAutoLoadMemory, crash_on_box);
  for (size_t k = 0; k < 2; ++k) {
    ASSERT_FALSE(warm[k].error) << *warm[k].error;
    ASSERT_TRUE(warm[k].sag);
    EXPECT_EQ(warm[k].sag->measured.resolution, cold[k].sag->measured.resolution);
    EXPECT_EQ(warm[k].sag->measured.design_edges, cold[k].sag->measured.design_edges);
    EXPECT_EQ(warm[k].pieces[0].vertices, cold[k].pieces[0].vertices);
  }
  // The sag used is the entry's: one stored under the file's key wins.
  StoredHulls fake = *entry;
  fake.sag = measured();
  ASSERT_EQ(write_cached_hulls(dir.string(), key, fake), "");
  const auto faked = build_parts(s, 1, {}, kDefaultLoadTimeout, cache);
  ASSERT_TRUE(faked[0].sag);
  EXPECT_EQ(faked[0].sag->measured.concave, 1.0 / 3.0);
  // A run without auto keeps the entry as it is (it finds its hulls there).
  ASSERT_FALSE(build_parts(box_scene("hull"), 1, {}, kDefaultLoadTimeout, cache)[0].error);
  ASSERT_TRUE(read_cached_hulls(dir.string(), key)->sag);
  fs::remove_all(dir);
}

TEST(HullCache, ARerunTakesTheHullsFromTheCache) {
  const fs::path dir = pd_test::absent_dir("hull_cache", "rerun");
  const PartsCache cache{dir.string()};
  const SceneSpec s = box_scene("hull");
  const auto cold = build_parts(s, 1, {}, kDefaultLoadTimeout, cache);
  ASSERT_FALSE(cold[0].error) << *cold[0].error;
  ASSERT_EQ(entries(dir, ".pdh").size(), 1u) << "one entry per file, not per instance";

  {
    // Without the cache the file must be read, and the crash shows.
    EXPECT_TRUE(
        build_parts(s, 1, {}, kDefaultLoadTimeout, {}, kAutoLoadMemory, crash_on_box)[0].error);
    // With it, pieces "hull" reads nothing: same parts.
    const auto warm =
        build_parts(s, 1, {}, kDefaultLoadTimeout, cache, kAutoLoadMemory, crash_on_box);
    ASSERT_EQ(warm.size(), 2u);
    for (size_t k = 0; k < 2; ++k) {
      ASSERT_FALSE(warm[k].error) << *warm[k].error;
      EXPECT_EQ(warm[k].vertex_count, cold[k].vertex_count);
      EXPECT_EQ(warm[k].pieces[0].vertices, cold[k].pieces[0].vertices);
      EXPECT_EQ(warm[k].box.lo, cold[k].box.lo);
    }
    // Pieces "auto" keeps the file's surface for the refinement: it reads the
    // file, until its convexity and surface are stored too (the mesh store).
    const auto with_surface = build_parts(box_scene("auto"), 1, {}, kDefaultLoadTimeout, cache,
                                          kAutoLoadMemory, crash_on_box);
    EXPECT_TRUE(with_surface[0].error);
    const auto auto_cold = build_parts(box_scene("auto"), 1, {}, kDefaultLoadTimeout, cache);
    ASSERT_FALSE(auto_cold[0].error) << *auto_cold[0].error;
    const auto auto_warm = build_parts(box_scene("auto"), 1, {}, kDefaultLoadTimeout, cache,
                                       kAutoLoadMemory, crash_on_box);
    ASSERT_FALSE(auto_warm[0].error) << *auto_warm[0].error;
    EXPECT_EQ(auto_warm[0].pieces[0].vertices, auto_cold[0].pieces[0].vertices);
    EXPECT_EQ(auto_warm[0].convex, auto_cold[0].convex);
    ASSERT_TRUE(auto_warm[0].surface);
    EXPECT_EQ(file_mesh_of(*auto_warm[0].surface)->triangles,
              file_mesh_of(*auto_cold[0].surface)->triangles);
    EXPECT_EQ(entries(dir / "meshes", ".pdm").size(), 1u);
  }

  // The hulls used are the entry's: one stored under the file's key wins over
  // the file's bytes (the file is the box; the entry is a box twice its size).
  const std::string key = hulls_key(file_content_hash(kBox), false);
  StoredHulls fake = *read_cached_hulls(dir.string(), key);
  fake.reduced[0] *= 2.0;
  ASSERT_EQ(write_cached_hulls(dir.string(), key, fake), "");
  for (const char* pieces : {"hull", "auto"}) {
    const auto parts = build_parts(box_scene(pieces), 1, {}, kDefaultLoadTimeout, cache);
    ASSERT_FALSE(parts[0].error) << pieces << ": " << *parts[0].error;
    EXPECT_DOUBLE_EQ(parts[0].box.hi.x() - parts[0].box.lo.x(),
                     2.0 * (cold[0].box.hi.x() - cold[0].box.lo.x()))
        << pieces;
    if (std::string(pieces) == "auto") {
      EXPECT_TRUE(parts[0].surface) << "the surface is kept";
    }
  }
  // Per-mesh pieces are another entry.
  const auto meshes = build_parts(box_scene("meshes"), 1, {}, kDefaultLoadTimeout, cache);
  ASSERT_FALSE(meshes[0].error);
  EXPECT_EQ(meshes[0].box.hi, cold[0].box.hi);
  EXPECT_EQ(entries(dir, ".pdh").size(), 2u);
}

namespace {

// An inline part of n points on a sphere of radius r (placed by `shift` along x).
std::string inline_part(const std::string& id, int n, double r, double shift) {
  std::string v;
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n, phi = 2.399963229728653 * i;
    const double s = std::sqrt(1.0 - z * z);
    v += (i ? "," : "") + std::string("[") + std::to_string(r * s * std::cos(phi)) + "," +
         std::to_string(r * s * std::sin(phi)) + "," + std::to_string(r * z) + "]";
  }
  return R"({"id": ")" + id + R"(", "vertices": [)" + v + R"(], "transform": [1,0,0,)" +
         std::to_string(shift) + R"(, 0,1,0,0, 0,0,1,0, 0,0,0,1]})";
}

}  // namespace

TEST(HullCache, LargeInlinePartsTakeTheirHullsFromTheCache) {
  const fs::path dir = pd_test::absent_dir("hull_cache", "inline");
  const PartsCache cache{dir.string()};
  const long big = tol::kInlineHullCacheVertices;
  auto scene = [&](double shift) {
    return parse_scene_json(R"({"tolerance": 0.1, "parts": [)" +
                                inline_part("big", static_cast<int>(big), 5.0, shift) + "," +
                                inline_part("small", 100, 5.0, 50.0) + "]}",
                            "s.json", "");
  };
  const auto cold = build_parts(scene(0.0), 1, {}, kDefaultLoadTimeout, cache);
  ASSERT_FALSE(cold[0].error);
  EXPECT_EQ(entries(dir, ".pdi").size(), 1u) << "the large part only";
  const auto warm = build_parts(scene(0.0), 1, {}, kDefaultLoadTimeout, cache);
  EXPECT_EQ(warm[0].pieces[0].vertices, cold[0].pieces[0].vertices);
  EXPECT_EQ(warm[0].vertex_count, big);
  // The entry under the part's key is what is used: a hull twice the size.
  const SceneSpec s = scene(0.0);
  const std::string key = inline_hull_key(vertex_digest(*s.parts[0].vertices),
                                          s.parts[0].to_scene_units, s.parts[0].transform);
  Hull fake = *read_cached_hull(dir.string(), key);
  fake.vertices *= 2.0;
  fake.warnings = {"from the test"};
  ASSERT_EQ(write_cached_hull(dir.string(), key, fake), "");
  const auto faked = build_parts(s, 1, {}, kDefaultLoadTimeout, cache);
  EXPECT_NEAR(faked[0].box.hi.x(), 2.0 * cold[0].box.hi.x(), 1e-9);
  EXPECT_EQ(faked[0].warnings, std::vector<std::string>{"from the test"});
  // Moved: another key, hulled again, and not the fake.
  const auto moved = build_parts(scene(1.0), 1, {}, kDefaultLoadTimeout, cache);
  EXPECT_NEAR(moved[0].box.hi.x(), cold[0].box.hi.x() + 1.0, 1e-9);
  EXPECT_EQ(entries(dir, ".pdi").size(), 2u);
}
