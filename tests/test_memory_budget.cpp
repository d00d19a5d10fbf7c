// Memory that follows the work (issue 45): the byte-bounded cache, the mesh
// store the parts stage leaves surfaces in, and a run whose largest process
// stays the same size when the assembly grows and its largest pair does not.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>

#include "byte_cache.h"
#include "cli_support.h"
#include "corpus/cad_shapes.h"
#include "geometry/same_position.h"
#include "memory_limit.h"
#include "scene/mesh_store.h"
#include "stl_file.h"

namespace {

using pd::ByteCache;
using pd::Mesh;
using pd::MeshStore;
using pd::Vec3;
using pd::shapes::Vec2;
using Cache = ByteCache<int, int>;

Cache::Built built(int v, size_t bytes) {
  return {std::make_shared<const int>(v), bytes};
}

TEST(ByteCache, BuildsOnceAndDropsTheLeastRecentlyUsedPastTheBudget) {
  Cache cache(250);
  int made = 0;
  const auto make = [&](int k) { return [&made, k] { return ++made, built(k, 100); }; };
  EXPECT_EQ(*cache.get(1, make(1)), 1);
  EXPECT_EQ(*cache.get(2, make(2)), 2);
  EXPECT_EQ(*cache.get(1, make(1)), 1);  // kept: 1 is now the most recent
  EXPECT_EQ(made, 2);
  EXPECT_EQ(*cache.get(3, make(3)), 3);  // 300 > 250: 2, the least recent, goes
  EXPECT_EQ(made, 3);
  cache.get(1, make(1));
  EXPECT_EQ(made, 3);
  cache.get(2, make(2));
  EXPECT_EQ(made, 4);
  EXPECT_EQ(cache.builds(), 4u);
  EXPECT_EQ(cache.hits(), 2u);
  EXPECT_EQ(cache.peak_bytes(), 300u);  // a value held past the budget only until the next drop
}

TEST(ByteCache, NeverDropsAValueInUse) {
  Cache cache(0);  // nothing is kept once let go
  const auto held = cache.get(1, [] { return built(1, 100); });
  int made = 0;
  cache.get(2, [&] { return ++made, built(2, 100); });
  cache.get(1, [&] { return ++made, built(1, 100); });  // still held above: not built again
  EXPECT_EQ(made, 1);
  cache.get(2, [&] { return ++made, built(2, 100); });  // let go: built again
  EXPECT_EQ(made, 2);
}

TEST(ByteCache, AnErasedValueGoesWhenItsLastHolderLetsItGo) {
  Cache cache(1000);
  int made = 0;
  std::weak_ptr<const int> seen;
  {
    const auto held = cache.get(1, [&] { return ++made, built(1, 100); });
    seen = held;
    cache.get(2, [&] { return ++made, built(2, 100); });
    cache.erase(1);
    cache.erase(3);                // never kept: nothing
    EXPECT_FALSE(seen.expired());  // still held here
  }
  EXPECT_TRUE(seen.expired());  // the cache kept it no longer
  cache.get(1, [&] { return ++made, built(1, 100); });
  cache.get(2, [&] { return ++made, built(2, 100); });  // kept
  EXPECT_EQ(made, 3);
  EXPECT_EQ(cache.drops(), 0u);  // an erase is no drop past the budget
}

TEST(ByteCache, AFailedBuildIsNotKeptAndOneBuildServesConcurrentCallers) {
  Cache cache(1000);
  EXPECT_THROW(cache.get(1, []() -> Cache::Built { throw std::runtime_error("no"); }),
               std::runtime_error);
  EXPECT_EQ(*cache.get(1, [] { return built(7, 1); }), 7);  // built again after the failure
  std::atomic<int> made{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&] {
      cache.get(2, [&] {
        ++made;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        return built(2, 1);
      });
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(made.load(), 1);
}

std::string fresh_dir(const std::string& name) {
  const std::string d =
      testing::TempDir() + "memory_budget_" + std::to_string(getpid()) + "_" + name + "/";
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

TEST(MeshStore, KeepsMeshesWholeAndMissesWhatIsDamaged) {
  const std::string d = fresh_dir("store");
  const auto store = MeshStore::in_cache(d);
  Mesh f32 = pd::shapes::float32(pd::shapes::translated(
      pd::shapes::cylinder(Vec2(0, 0), 3, 0, 10, 24), Vec3(21000.5, -3000.25, 7)));
  Mesh f64 = f32;
  f64.vertices(0, 0) += 1e-9;  // not a float: kept as a double
  ASSERT_EQ(store->put("a", f32), "");
  ASSERT_EQ(store->put("b", f64), "");
  for (const auto& [key, m] : {std::pair{"a", &f32}, std::pair{"b", &f64}}) {
    ASSERT_TRUE(store->has(key));
    const auto back = store->get(key);
    ASSERT_TRUE(back) << key;
    const Mesh w = pd::welded(*m, pd::first_at_same_position(m->vertices));
    EXPECT_EQ(back->vertices, w.vertices) << key;
    EXPECT_EQ(back->triangles, w.triangles) << key;
  }
  // Stored welded: an STL file's corners (three a triangle) come back each once.
  Mesh soup;
  soup.vertices.resize(3, 3 * f32.triangles.cols());
  soup.triangles.resize(3, f32.triangles.cols());
  for (long t = 0; t < f32.triangles.cols(); ++t)
    for (int k = 0; k < 3; ++k) {
      soup.vertices.col(3 * t + k) = f32.vertices.col(f32.triangles(k, t));
      soup.triangles(k, t) = int(3 * t + k);
    }
  ASSERT_EQ(store->put("soup", soup), "");
  const auto back = store->get("soup");
  ASSERT_TRUE(back);
  EXPECT_EQ(back->vertices.cols(),
            pd::distinct_positions(f32.vertices, pd::first_at_same_position(f32.vertices)).cols());
  ASSERT_EQ(back->triangles.cols(), soup.triangles.cols());
  for (long t = 0; t < soup.triangles.cols(); ++t)
    for (int k = 0; k < 3; ++k)
      EXPECT_TRUE(back->vertices.col(back->triangles(k, t)) ==
                  soup.vertices.col(soup.triangles(k, t)));
  EXPECT_LT(std::filesystem::file_size(d + "meshes/a.pdm"),
            std::filesystem::file_size(d + "meshes/b.pdm"));
  EXPECT_FALSE(store->has("c"));
  EXPECT_FALSE(store->get("c"));
  const std::string entry = d + "meshes/a.pdm";
  std::filesystem::resize_file(entry, std::filesystem::file_size(entry) - 1);
  EXPECT_FALSE(store->has("a"));
  EXPECT_FALSE(store->get("a"));
  // A B-rep surface's per-triangle sags, beside its mesh: whole, or a miss.
  const std::vector<float> sags = {0.0f, 0.0125f, 0.0285f};
  ASSERT_EQ(store->put_sags("b", sags), "");
  EXPECT_EQ(store->get_sags("b"), sags);
  EXPECT_FALSE(store->get_sags("a"));
  const std::string sag_entry = d + "meshes/b.pds";
  std::filesystem::resize_file(sag_entry, std::filesystem::file_size(sag_entry) - 1);
  EXPECT_FALSE(store->get_sags("b"));
  // A surface's hull and facets as convex_hull found them: to the bit, or a miss.
  pd::HullTriangles facets;
  const pd::Points hull = pd::convex_hull(f64.vertices, &facets).vertices;
  ASSERT_FALSE(facets.triangles.empty());
  ASSERT_EQ(store->put_hull("b", hull, facets), "");
  const auto kept = store->get_hull("b");
  ASSERT_TRUE(kept);
  EXPECT_EQ(kept->first, hull);
  EXPECT_EQ(kept->second.triangles, facets.triangles);
  EXPECT_EQ(kept->second.normals, facets.normals);
  EXPECT_FALSE(store->get_hull("a"));
  const std::string hull_entry = d + "meshes/b.pdh";
  std::filesystem::resize_file(hull_entry, std::filesystem::file_size(hull_entry) - 1);
  EXPECT_FALSE(store->get_hull("b"));
  std::string dir;
  {
    const auto temporary = MeshStore::temporary();
    dir = temporary->dir();
    ASSERT_EQ(temporary->put("x", f32), "");
    EXPECT_TRUE(std::filesystem::exists(dir));
    EXPECT_FALSE(temporary->persistent());
  }
  EXPECT_FALSE(std::filesystem::exists(dir)) << "a temporary store goes with its last reference";
}

TEST(MemoryBudget, MemoryIsAnAmountOrAnError) {
  EXPECT_DOUBLE_EQ(pd::parse_memory_mb("512M"), 512);
  EXPECT_DOUBLE_EQ(pd::parse_memory_mb("1.5G"), 1536);
  EXPECT_DOUBLE_EQ(pd::parse_memory_mb("2048"), 2048);
  EXPECT_DOUBLE_EQ(pd::parse_memory_mb("64MB"), 64);
  EXPECT_DOUBLE_EQ(pd::memory_budget_mb(24000), 1024);
  EXPECT_DOUBLE_EQ(pd::memory_budget_mb(4000), 500);
  EXPECT_DOUBLE_EQ(pd::memory_budget_mb(1000), 256);
  for (const char* bad : {"", "0", "-5M", "lots", "5X", "nanM", "infG"}) {
    EXPECT_THROW(pd::parse_memory_mb(bad), std::invalid_argument) << bad;
    const auto r = pd::test::pdcheck(pd::test::kSource +
                                     "/testdata/demo/scene.json --quiet --memory '" + bad + "'");
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_NE(r.err.find("--memory"), std::string::npos) << r.err;
  }
}

// `copies` rings on shafts 0.3 too thick for their bores (each pair refined on its surfaces),
// every file distinct, on a line 100 apart; the scene's path.
std::string rings_on_shafts(const std::string& dir, int copies) {
  std::vector<Vec2> profile;  // a ring 10–16 wide, with a wavy outer wall: nonconvex, many facets
  for (int k = 0; k <= 60; ++k)
    profile.push_back(Vec2(16 + 0.3 * std::sin(k * 0.7), 20.0 * k / 60));
  profile.push_back(Vec2(10, 20));
  profile.push_back(Vec2(10, 0));
  std::reverse(profile.begin(), profile.end());
  std::string parts;
  for (int c = 0; c < copies; ++c) {
    const Vec3 at(20000 + 100 * c, 5000, 300);
    const std::string ring = "ring" + std::to_string(c) + ".stl",
                      shaft = "shaft" + std::to_string(c) + ".stl";
    pd::test::write_binary_stl(dir + ring,
                               pd::shapes::translated(pd::shapes::revolution(profile, 400), at));
    pd::test::write_binary_stl(
        dir + shaft,
        pd::shapes::translated(pd::shapes::cylinder(Vec2(0, 0), 10.3, -5, 25, 64 + c), at));
    parts += std::string(c ? "," : "") + R"({"id": "ring)" + std::to_string(c) + R"(", "mesh": ")" +
             ring + R"("}, {"id": "shaft)" + std::to_string(c) + R"(", "mesh": ")" + shaft + "\"}";
  }
  std::ofstream(dir + "scene.json") << R"({"tolerance": 0.05, "parts": [)" + parts + "]}";
  return dir + "scene.json";
}

// The largest resident size (MB) among the processes of `cmd` (pdcheck and
// the workers and loaders it waited for), from a child of our own so that
// earlier runs do not count.
double peak_process_mb(const std::string& cmd) {
  int fd[2];
  if (pipe(fd) != 0) throw std::runtime_error("pipe");
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    const int rc = std::system((cmd + " >/dev/null 2>&1").c_str());
    rusage u{};
    getrusage(RUSAGE_CHILDREN, &u);
    const long kb = WIFEXITED(rc) && WEXITSTATUS(rc) <= 1 ? u.ru_maxrss : -1;
    (void)!write(fd[1], &kb, sizeof kb);
    _exit(0);
  }
  close(fd[1]);
  long kb = -1;
  (void)!read(fd[0], &kb, sizeof kb);
  close(fd[0]);
  waitpid(pid, nullptr, 0);
  return kb / 1024.0;
}

TEST(MemoryBudget, TheLargestProcessFollowsTheLargestPairNotTheAssembly) {
  // 2 and 8 copies of the same ring-on-shaft pair (48,000-triangle rings):
  // with a small budget no process holds more than a pair's surfaces and
  // distances, so the 4× larger assembly needs no more memory. (Before the
  // parts stage let its meshes go, the 8 copies took the parent ~150 MB more.)
  if (!pd::can_cap_address_space())  // false exactly in an AddressSanitizer build
    GTEST_SKIP() << "resident sizes under AddressSanitizer hold its quarantine and shadow memory";
  const std::string small = fresh_dir("two"), large = fresh_dir("eight");
  const std::string args = " --no-cache --jobs 1 --memory 1M";
  const double two =
      peak_process_mb(pd_test::pdcheck_binary_for("") + " " + rings_on_shafts(small, 2) + args);
  const double eight =
      peak_process_mb(pd_test::pdcheck_binary_for("") + " " + rings_on_shafts(large, 8) + args);
  ASSERT_GT(two, 0) << "pdcheck failed on the two copies";
  ASSERT_GT(eight, 0) << "pdcheck failed on the eight copies";
  EXPECT_LT(eight, two * 1.15 + 8) << "two copies: " << two << " MB, eight: " << eight << " MB";
  // Under the default budget, which would hold every copy's distances, too:
  // a part's go after its last pair.
  const std::string roomy_args = " --no-cache --jobs 1";
  const double two_roomy =
      peak_process_mb(pd_test::pdcheck_binary_for("") + " " + small + "scene.json" + roomy_args);
  const double eight_roomy =
      peak_process_mb(pd_test::pdcheck_binary_for("") + " " + large + "scene.json" + roomy_args);
  EXPECT_LT(eight_roomy, two_roomy * 1.15 + 8)
      << "default budget: two copies: " << two_roomy << " MB, eight: " << eight_roomy << " MB";
  // And the results are those of a run with room to keep everything, on two workers.
  const auto tight = pd::test::pdcheck(large + "scene.json" + args);
  const auto roomy = pd::test::pdcheck(large + "scene.json --no-cache --jobs 2 --memory 4G");
  ASSERT_EQ(tight.code, roomy.code) << tight.err << roomy.err;
  auto pairs = [](const std::string& out) {
    auto j = nlohmann::json::parse(out)["pairs"];
    for (auto& p : j) p.erase("time_ms");
    return j;
  };
  EXPECT_EQ(pairs(tight.out), pairs(roomy.out));
  for (const auto& p : pairs(tight.out)) EXPECT_NE(p["depth_source"], "hull") << p;
}

}  // namespace
