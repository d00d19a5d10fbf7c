// Nonconvex parts end to end: scripts/make_nonconvex.py writes an assembly whose
// nominal relations are known by construction (bolts in holes, pins in bores,
// L-brackets, a drilled board, a hollow housing, a buried part, an open tray);
// pdcheck must recover every one, and a cached rerun must repeat the cold run.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "batch/refine_cache.h"
#include "scene/convexity_cache.h"
#include "scratch_dir.h"

using namespace pd;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

const std::string kSource = PDCHECK_SOURCE_DIR;

struct Run {
  int code = -1;
  std::string out;
};

Run shell(const std::string& cmd) {
  Run r;
  FILE* p = popen((cmd + " 2>/dev/null </dev/null").c_str(), "r");
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

json read_json(const fs::path& p) {
  std::ifstream in(p);
  return json::parse(in);
}

// 8-gon holes and bores keep each decomposition well inside its time box (about a
// second per test; tol::kDecomposeSeconds is never reached, so runs are reproducible).
fs::path generate(const std::string& name, const std::string& args = "--segments 8") {
  const fs::path d = pd_test::scratch_dir("nonconvex", name);
  const Run g =
      shell("python3 " + kSource + "/scripts/make_nonconvex.py " + d.string() + " " + args);
  EXPECT_EQ(g.code, 0);
  return d;
}

json pdcheck(const fs::path& dir, const std::string& args, int* code = nullptr) {
  const Run r = shell(std::string(PDCHECK_BINARY) + " " + (dir / "scene.json").string() +
                      " --quiet --jobs 2 " + args);
  if (code) *code = r.code;
  return r.out.empty() ? json() : json::parse(r.out);
}

std::string key(const std::string& a, const std::string& b) {
  return a < b ? a + ":" + b : b + ":" + a;
}

std::map<std::string, json> by_pair(const json& report) {
  std::map<std::string, json> m;
  for (const auto& p : report["pairs"]) m[key(p["a"], p["b"])] = p;
  return m;
}

bool recovered(const std::string& expect, const std::string& status) {
  if (expect == "interference") return status == "interference";
  if (expect == "contact") return status == "separated" || status == "false_positive";
  return status == "separated";  // clearance
}

json without_timings(json r) {
  r.erase("seconds");
  r.erase("stage_seconds");
  for (auto& p : r["pairs"]) p.erase("time_ms");
  for (auto& p : r["parts"]) p.erase("cached");
  return r;
}

json without_decomposition_times(json r) {
  for (auto& p : r["parts"]) p.erase("decomposition_seconds");
  return r;
}

}  // namespace

TEST(Nonconvex, EveryNominalRelationIsRecovered) {
  const fs::path d = generate("nonconvex_nominal");
  const json expected = read_json(d / "expected.json");
  const fs::path cache = d / "cache";
  int code = -1;
  const json rep = pdcheck(d, "--pieces auto --cache " + cache.string(), &code);
  ASSERT_TRUE(rep.is_object());
  const auto pairs = by_pair(rep);
  std::set<std::string> listed;
  for (const auto& e : expected["pairs"]) {
    const std::string k = key(e["a"], e["b"]);
    listed.insert(k);
    ASSERT_TRUE(pairs.count(k)) << k << " is not a candidate pair";
    const json& p = pairs.at(k);
    EXPECT_TRUE(recovered(e["expect"], p["status"]))
        << k << " (" << e["why"].get<std::string>() << "): expected " << e["expect"] << ", got "
        << p.dump();
    // No hull artefact is reported as a confirmed interference.
    if (e["expect"] != "interference" && p["status"] == "interference") {
      EXPECT_FALSE(p.value("confirmed", true)) << k;
    }
  }
  for (const auto& [k, p] : pairs) EXPECT_TRUE(listed.count(k)) << "unexpected pair " << k;
  EXPECT_EQ(code, 1);  // the genuine interferences
  // Convexity as built: every part the generator calls nonconvex is measured so.
  for (const auto& part : rep["parts"]) {
    const json& info = expected["parts"][part["id"].get<std::string>()];
    if (!info["convex"].get<bool>()) {
      EXPECT_EQ(part["convex"], false) << part["id"];
    }
  }

  // No whole part is decomposed: the pairs are decided where the parts meet.
  for (const auto& part : rep["parts"]) EXPECT_FALSE(part.contains("cached")) << part["id"];
  // A rerun takes the refined pairs from the cache and repeats the cold run.
  long entries = 0;
  for (const auto& f : fs::directory_iterator(cache)) entries += f.path().extension() == ".pdr";
  EXPECT_GT(entries, 0);
  const json again = pdcheck(d, "--pieces auto --cache " + cache.string());
  EXPECT_EQ(without_timings(rep), without_timings(again));
}

TEST(Nonconvex, HullOnlyReportsTheArtefacts) {
  // The same assembly with --pieces hull: the hulls fill every hole and corner,
  // so the relations above are lost (what the refinement is for).
  const fs::path d = generate("nonconvex_hull");
  const json expected = read_json(d / "expected.json");
  const auto pairs = by_pair(pdcheck(d, "--pieces hull --no-cache"));
  int artefacts = 0;
  for (const auto& e : expected["pairs"]) {
    const std::string k = key(e["a"], e["b"]);
    if (e["expect"] != "interference" && pairs.count(k) && pairs.at(k)["status"] == "interference")
      ++artefacts;
  }
  EXPECT_GE(artefacts, 5);
}

TEST(Nonconvex, ACorruptCacheEntryIsRecomputed) {
  const fs::path d = generate("nonconvex_cache");
  const fs::path cache = d / "cache";
  const json cold = pdcheck(d, "--pieces auto --cache " + cache.string());
  int entries = 0;
  for (const auto& f : fs::recursive_directory_iterator(cache)) {
    if (!f.is_regular_file()) continue;
    ++entries;
    // Truncate every entry (the mesh store's too): a reader must not trust it.
    fs::resize_file(f.path(), fs::file_size(f.path()) / 2);
  }
  ASSERT_GT(entries, 0);
  const json warm = pdcheck(d, "--pieces auto --cache " + cache.string());
  for (const auto& part : warm["parts"])
    if (part.contains("cached")) {
      EXPECT_FALSE(part["cached"].get<bool>()) << part["id"];
    }
  EXPECT_EQ(without_decomposition_times(without_timings(cold)),
            without_decomposition_times(without_timings(warm)));
}

// The refinement cache: a rerun takes each refined pair's result from it (seen
// by marking every stored result), and a part moved since misses it.
TEST(Nonconvex, RefinedPairsComeFromTheCacheUntilAPlacementChanges) {
  const fs::path d = generate("nonconvex_pair_cache");
  const fs::path cache = d / "cache";
  const json cold = pdcheck(d, "--pieces auto --cache " + cache.string());
  ASSERT_TRUE(cold.is_object());
  int entries = 0;
  for (const auto& f : fs::directory_iterator(cache)) {
    if (f.path().extension() != ".pdr") continue;
    const std::string key = f.path().stem().string();
    auto stored = read_cached_refinement(cache.string(), key);
    ASSERT_TRUE(stored) << f.path();
    stored->result.depth_source = "from-cache";
    ASSERT_EQ(write_cached_refinement(cache.string(), key, *stored), "");
    ++entries;
  }
  ASSERT_GT(entries, 3);
  auto refined = [](const json& report) {
    std::map<std::string, std::string> m;
    for (const auto& p : report["pairs"])
      if (p.contains("hull_depth")) m[key(p["a"], p["b"])] = p["depth_source"];
    return m;
  };
  const auto before = refined(cold);
  ASSERT_GT(before.size(), 3u);
  const auto warm = refined(pdcheck(d, "--pieces auto --cache " + cache.string()));
  EXPECT_EQ(warm.size(), before.size());
  for (const auto& [k, source] : before) {
    ASSERT_TRUE(warm.count(k)) << k;
    EXPECT_EQ(warm.at(k), "from-cache") << k;
  }

  // Move the clearance-fit bolt by 0.1 mm (still clear of its hole).
  json scene = read_json(d / "scene.json");
  for (auto& part : scene["parts"])
    if (part["id"] == "c0_bolt_clear")
      part["transform"] = {{1, 0, 0, 0.1}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  std::ofstream(d / "scene.json") << scene.dump();
  const auto after = refined(pdcheck(d, "--pieces auto --cache " + cache.string()));
  const std::string moved = key("c0_plate", "c0_bolt_clear");
  ASSERT_TRUE(after.count(moved));
  EXPECT_EQ(after.at(moved), "mesh-test");  // recomputed: the bolt is still clear
  EXPECT_EQ(after.size(), before.size());
  for (const auto& [k, source] : after) {
    if (k.find("c0_bolt_clear") == std::string::npos) {
      EXPECT_EQ(source, "from-cache") << k;
    }
  }
}

// The convexity cache: a rerun takes each mesh file's measured nonconvexity
// from it (seen by storing "convex" for every file), measuring none again.
TEST(Nonconvex, ConvexityComesFromTheCache) {
  const fs::path d = generate("nonconvex_convexity_cache");
  const fs::path cache = d / "cache";
  const json cold = pdcheck(d, "--pieces auto --cache " + cache.string());
  ASSERT_TRUE(cold.is_object());
  int nonconvex = 0;
  std::set<std::string> measured;  // where a pair needed it (batch/convexity_on_demand.h)
  for (const auto& p : cold["parts"]) {
    nonconvex += p.value("convex", true) ? 0 : 1;
    if (p.contains("convex")) measured.insert(p["id"].get<std::string>());
  }
  ASSERT_GT(nonconvex, 3);
  int entries = 0;
  for (const auto& f : fs::directory_iterator(cache)) {
    if (f.path().extension() != ".pdv") continue;
    const std::string key = f.path().stem().string();
    auto stored = read_cached_convexity(cache.string(), key);
    ASSERT_TRUE(stored) << f.path();
    ASSERT_EQ(write_cached_convexity(cache.string(), key, {0.0, stored->closed}), "");
    ++entries;
  }
  EXPECT_GE(entries, nonconvex);  // every measured mesh file
  const json warm = pdcheck(d, "--pieces auto --cache " + cache.string());
  ASSERT_EQ(warm["parts"].size(), cold["parts"].size());
  for (const auto& p : warm["parts"])
    if (measured.count(p["id"].get<std::string>())) {
      ASSERT_TRUE(p.contains("convex")) << p["id"];
      EXPECT_TRUE(p["convex"].get<bool>()) << p["id"];
    }
}

TEST(Nonconvex, ConvexOnlySceneReportIsUnchangedApartFromTheNewFields) {
  // The generator's convex parts alone (bolts, pins, blocks, a rod): --pieces
  // hull and the default (auto) report the same, apart from the new fields.
  const fs::path d = generate("nonconvex_convex_only");
  const json expected = read_json(d / "expected.json");
  json scene = read_json(d / "scene.json");
  json kept = json::array();
  for (const auto& p : scene["parts"])
    if (expected["parts"][p["id"].get<std::string>()]["convex"].get<bool>()) kept.push_back(p);
  // Copies of a bolt moved 0.5 (deep overlap), 9.98 (a tessellation-sized one)
  // and 10 (touching) along x: convex pairs of every status.
  for (const double dx : {0.5, 9.98, 10.0})
    kept.push_back({{"id", "bolt+" + std::to_string(dx)},
                    {"mesh", "c0_bolt_exact.stl"},
                    {"transform", {{1, 0, 0, dx}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}});
  scene["parts"] = kept;
  std::ofstream(d / "scene.json") << scene.dump();
  json hull = without_timings(pdcheck(d, "--pieces hull --no-cache"));
  json auto_ = without_timings(pdcheck(d, "--no-cache"));
  ASSERT_GE(auto_["pairs"].size(), 4u);
  // Convexity is measured where a pair's verdict turns on it: every part of an
  // interfering pair, and no other.
  std::set<std::string> interfering;
  for (const auto& p : auto_["pairs"])
    if (p["status"] == "interference")
      interfering.insert({p["a"].get<std::string>(), p["b"].get<std::string>()});
  ASSERT_FALSE(interfering.empty());
  for (auto& p : auto_["parts"]) {
    EXPECT_EQ(p.contains("convex"), interfering.count(p["id"].get<std::string>()) > 0) << p["id"];
    if (p.contains("convex")) {
      EXPECT_EQ(p["convex"], true) << p["id"];
    }
    p.erase("convex");
  }
  for (auto* r : {&hull, &auto_})
    for (auto& p : (*r)["pairs"]) {
      EXPECT_EQ(p["depth_source"], "hull");
      p.erase("depth_source");
    }
  for (auto& p : hull["pairs"]) EXPECT_FALSE(p.contains("confirmed"));
  for (auto& p : auto_["pairs"]) {  // the hulls hold parts that might have been nonconvex
    EXPECT_EQ(p["confirmed"], true) << p["a"] << " " << p["b"];
    p.erase("confirmed");
  }
  // Pieces are part of a part's content hash (--reuse solves such pairs again).
  for (auto* r : {&hull, &auto_}) {
    r->erase("hashes");
    for (auto& p : (*r)["parts"]) p.erase("content_hash");
  }
  EXPECT_EQ(hull, auto_);
}

// Sharded (docs/scale-out.md): shards 1..3 of the nonconvex assembly, sharing
// one cache as shards on one machine do, merged, give the unsharded run's
// report: every refined pair, its pieces and bounds, every part's convexity and
// decomposition.
TEST(Nonconvex, ShardsMergedEqualTheUnshardedRun) {
  const fs::path d = generate("nonconvex_shards");
  int code = -1;
  const json full = pdcheck(d, "--cache " + (d / "cache_full").string(), &code);
  ASSERT_TRUE(full.is_object());
  ASSERT_EQ(code, 1);
  bool refined = false;
  for (const auto& p : full["pairs"]) refined |= p.value("depth_source", "hull") != "hull";
  ASSERT_TRUE(refined) << "no pair looked past the hulls";
  std::string shards;
  for (int k = 1; k <= 3; ++k) {
    const std::string out = (d / ("shard" + std::to_string(k) + ".json")).string();
    int shard_code = -1;
    pdcheck(d,
            "--shard " + std::to_string(k) + "/3 -o " + out + " --cache " +
                (d / "cache_shards").string(),
            &shard_code);
    EXPECT_EQ(shard_code, 0) << "shard " << k;
    shards += " " + out;
  }
  const auto m = shell(std::string(PDCHECK_BINARY) + " merge -q" + shards);
  EXPECT_EQ(m.code, code);
  ASSERT_FALSE(m.out.empty());
  EXPECT_EQ(without_decomposition_times(without_timings(json::parse(m.out))),
            without_decomposition_times(without_timings(full)));
}
