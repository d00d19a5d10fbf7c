// Inline vertex lists kept as a summary (scene/inline_vertices.cpp). A shard's
// scene load (load_scene_file with keep_vertices false): it keeps a
// VertexSummary, not the vertices, of every inline part; its plan and content
// hashes are those of the whole load, and read_inline_vertices gives back the
// very same vertices of the parts it loads, or refuses a file changed since.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <random>
#include <vector>

#include "batch/content_hashes.h"
#include "batch/shard.h"
#include "cli_support.h"
#include "scene/scene.h"

using nlohmann::json;
using namespace pd::test;

namespace {

// Parts of 10-40 random vertices on a row of overlapping neighbours, some with
// their own units or a rotating transform, one moving, one mesh part.
json generated_scene(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 3.0);
  json parts = json::array();
  for (int k = 0; k < 40; ++k) {
    json v = json::array();
    const int n = 10 + static_cast<int>(rng() % 31);
    for (int i = 0; i < n; ++i) v.push_back({2.0 * k + u(rng), u(rng), u(rng) + 0.1 * i});
    json p = {{"id", "p" + std::to_string(k)}, {"vertices", v}};
    if (k % 5 == 1) p["units"] = "cm";
    if (k % 7 == 3)  // a quarter turn about z, then a shift
      p["transform"] = {0, -1, 0, 2.0 * k, 1, 0, 0, 0.5, 0, 0, 1, 0.25, 0, 0, 0, 1};
    if (k == 11) p["motion"] = {{"velocity", {0.5, 0, 0}}};
    parts.push_back(p);
  }
  parts.push_back({{"id", "mesh"}, {"mesh", kSource + "/testdata/formats/box.obj"}});
  return {{"units", "mm"},
          {"tolerance", 0.01},
          {"checks", {{"motion", {{"t1", 2.0}, {"dt", 0.5}}}}},
          {"parts", parts}};
}

std::string temp_scene(const std::string& name, const std::string& text) {
  return write_temp("shard_scan_" + std::to_string(getpid()) + "_" + name, text);
}

bool same_bits(const pd::Points& a, const pd::Points& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<size_t>(a.size())) == 0;
}

}  // namespace

TEST(ShardScan, KeepsSummariesThatPlanAndHashAsTheVertices) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const std::string path = temp_scene("plan.json", generated_scene(seed).dump(1));
    for (int threads : {1, 3}) {
      const pd::SceneSpec whole = pd::load_scene_file(path, std::nullopt, threads);
      const pd::SceneSpec shard = pd::load_scene_file(path, std::nullopt, threads, false);
      ASSERT_EQ(whole.parts.size(), shard.parts.size());
      long summarized = 0;
      for (size_t k = 0; k < whole.parts.size(); ++k) {
        const pd::PartSpec& w = whole.parts[k];
        const pd::PartSpec& s = shard.parts[k];
        EXPECT_FALSE(w.vertex_summary);
        if (w.mesh || w.motion) {  // mesh parts have no list; a moving part's is swept by the plan
          EXPECT_FALSE(s.vertex_summary) << w.id;
          EXPECT_EQ(s.vertices.has_value(), w.vertices.has_value()) << w.id;
          continue;
        }
        ASSERT_TRUE(s.vertex_summary) << w.id;
        EXPECT_FALSE(s.vertices) << w.id << ": a shard holds only the summary";
        EXPECT_EQ(s.vertex_summary->count, w.vertices->cols()) << w.id;
        ++summarized;
      }
      EXPECT_EQ(summarized, 39);
      EXPECT_EQ(pd::part_content_hashes(shard), pd::part_content_hashes(whole));

      for (int n : threads == 1 ? std::vector<int>{3, 7} : std::vector<int>{3}) {
        const pd::ScenePlan a = pd::plan_scene(whole, n, 1, 0.0);
        const pd::ScenePlan b = pd::plan_scene(shard, n, 1, 0.0);
        ASSERT_EQ(a.boxes.size(), b.boxes.size());
        for (size_t k = 0; k < a.boxes.size(); ++k) {
          ASSERT_EQ(a.boxes[k].has_value(), b.boxes[k].has_value()) << k;
          if (!a.boxes[k]) continue;
          EXPECT_EQ(a.boxes[k]->lo, b.boxes[k]->lo) << "part " << k << ", seed " << seed;
          EXPECT_EQ(a.boxes[k]->hi, b.boxes[k]->hi) << "part " << k << ", seed " << seed;
        }
        EXPECT_EQ(a.vertices, b.vertices);
        EXPECT_GT(a.pairs.size(), 10u);
        EXPECT_EQ(a.pairs, b.pairs);
        EXPECT_EQ(a.pair_shard, b.pair_shard);
        EXPECT_EQ(a.owner, b.owner);
      }

      // The parts of one shard, read again: the whole load's vertices, bit for bit.
      pd::SceneSpec some = shard;
      some.parts.clear();
      for (size_t k = 0; k < shard.parts.size(); k += 3) some.parts.push_back(shard.parts[k]);
      pd::read_inline_vertices(some);
      for (size_t j = 0; j < some.parts.size(); ++j) {
        const pd::PartSpec& w = whole.parts[3 * j];
        EXPECT_FALSE(some.parts[j].vertex_summary);
        EXPECT_EQ(some.parts[j].vertices.has_value(), w.vertices.has_value());
        if (w.vertices) {
          EXPECT_TRUE(same_bits(*some.parts[j].vertices, *w.vertices)) << w.id;
        }
      }
    }
  }
}

TEST(ShardScan, RefusesASceneFileChangedSinceItWasRead) {
  const json doc = generated_scene(4);
  const std::string path = temp_scene("changed.json", doc.dump(1));
  pd::SceneSpec shard = pd::load_scene_file(path, std::nullopt, 1, false);
  {
    pd::SceneSpec again = shard;  // unchanged: read back
    EXPECT_NO_THROW(pd::read_inline_vertices(again));
  }
  // The same length, one digit of p5's list changed: the list still reads, to other numbers.
  const size_t changed = 5;
  ASSERT_TRUE(shard.parts[changed].vertex_summary);
  const pd::VertexSummary& sum = *shard.parts[changed].vertex_summary;
  std::string text = read_text(path);
  const size_t digit = text.find_first_of("123456789", sum.offset);
  ASSERT_LT(digit, sum.offset + sum.length);
  text[digit] = text[digit] == '9' ? '8' : static_cast<char>(text[digit] + 1);
  temp_scene("changed.json", text);
  pd::SceneSpec one = shard;
  one.parts = {shard.parts[changed]};
  try {
    pd::read_inline_vertices(one);
    ADD_FAILURE() << "a changed list was taken";
  } catch (const pd::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("\"" + shard.parts[changed].id + "\""), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("changed"), std::string::npos) << e.what();
  }
  pd::SceneSpec other = shard;  // a part whose list did not change still reads
  other.parts = {shard.parts[changed == 0 ? 1 : 0]};
  EXPECT_NO_THROW(pd::read_inline_vertices(other));
}

TEST(InlineVertices, PlacedInSceneUnitsThenTransformed) {
  pd::Points p(3, 2);
  p << 1, 0,  //
      0, 2,   //
      0, 0;
  pd::PartSpec spec;
  spec.to_scene_units = 10;       // cm in a mm scene
  spec.transform << 0, -1, 0, 5,  // a quarter turn about z, then a shift
      1, 0, 0, 0,                 //
      0, 0, 1, 1,                 //
      0, 0, 0, 1;
  const pd::Points placed = pd::place_points(p, spec);
  EXPECT_EQ(placed.col(0), pd::Vec3(5, 10, 1));   // (10, 0, 0) turned to (0, 10, 0)
  EXPECT_EQ(placed.col(1), pd::Vec3(-15, 0, 1));  // (0, 20, 0) turned to (-20, 0, 0)
}

TEST(InlineVertices, TheDigestIsTheListsBits) {
  // Each list made afresh (copies of one list make gcc -O1 warn, wrongly,
  // that Eigen's copy reads uninitialised memory).
  const auto list = [] {
    pd::Points p(3, 2);
    p << 1, 0.1, 0, 2, -0.0, 3;
    return p;
  };
  const pd::Points p = list(), same = list();
  EXPECT_EQ(pd::vertex_digest(p), pd::vertex_digest(same));
  pd::Points signed_zero = list();
  signed_zero(2, 0) = 0.0;  // +0 for -0: equal numbers, other bits
  EXPECT_NE(pd::vertex_digest(p), pd::vertex_digest(signed_zero));
  pd::Points last_bit = list();
  last_bit(0, 1) = std::nextafter(0.1, 1.0);
  EXPECT_NE(pd::vertex_digest(p), pd::vertex_digest(last_bit));
}
