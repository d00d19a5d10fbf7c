// The refinement cache's key and entries (batch/refine_cache.h): every input
// that changes a refined result changes the key; an entry reads back exactly,
// and a damaged or foreign one is never trusted.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "batch/refine_cache.h"
#include "batch/run.h"
#include "hash.h"

using namespace pd;
namespace fs = std::filesystem;

namespace {

Part mesh_part(const std::string& hash, double dx) {
  Part p;
  p.id = "p";
  p.mode = Pieces::kAuto;
  p.convex = false;
  Points v(3, 4);
  v << 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1;
  v.row(0).array() += dx;
  Hull h;
  h.vertices = v;
  p.pieces = {h};
  PartSurface s;
  s.file_hash = hash;
  s.placement(0, 3) = dx;
  p.surface = s;
  return p;
}

fs::path fresh_dir() {
  const fs::path d = fs::path(testing::TempDir()) / ("refine_cache_" + std::to_string(getpid()));
  fs::remove_all(d);
  return d;
}

}  // namespace

TEST(RefineCache, KeyFollowsEveryInput) {
  const Part a = mesh_part("aaaa", 0.0), b = mesh_part("bbbb", 0.0);
  PairResult hull;
  hull.status = Status::kInterference;
  hull.depth = 0.5;
  RunOptions o;
  o.tolerance = 0.05;
  const std::string k = refinement_key(a, b, hull, o, {});
  EXPECT_EQ(k, refinement_key(a, b, hull, o, {}));
  EXPECT_NE(k, refinement_key(b, a, hull, o, {}));
  EXPECT_NE(k, refinement_key(a, mesh_part("bbbb", 1e-9), hull, o, {}));  // placement
  EXPECT_NE(k, refinement_key(a, mesh_part("cccc", 0.0), hull, o, {}));   // content
  Part hull_mode = b;
  hull_mode.mode = Pieces::kDecompose;
  EXPECT_NE(k, refinement_key(a, hull_mode, hull, o, {}));
  RunOptions t = o;
  t.tolerance = 0.06;
  EXPECT_NE(k, refinement_key(a, b, hull, t, {}));
  RunOptions m = o;
  m.solver.method = Method::kExact;
  EXPECT_NE(k, refinement_key(a, b, hull, m, {}));
  RunOptions seed = o;
  seed.solver.seed = 2;
  EXPECT_NE(k, refinement_key(a, b, hull, seed, {}));
  PairChecks clearance;
  clearance.clearance = 0.2;
  EXPECT_NE(k, refinement_key(a, b, hull, o, clearance));
  PairResult other = hull;
  other.depth = 0.6;
  EXPECT_NE(k, refinement_key(a, b, other, o, {}));
}

TEST(RefineCache, EntriesReadBackAndDamageIsIgnored) {
  const fs::path dir = fresh_dir();
  PairResult r;
  r.a = 3, r.b = 7;
  r.status = Status::kFalsePositive;
  r.depth = 0.1 / 3.0;
  r.direction = Vec3(0.6, 0.0, 0.8);
  r.depth_source = "pieces";
  r.pieces = {{2, 5}};
  r.hull_depth = 1.25;
  r.depth_bounds = {{0.01, 1.25}};
  r.confirmed = true;
  ASSERT_EQ(write_cached_refinement(dir.string(), "k1", {r, true}), "");
  auto back = read_cached_refinement(dir.string(), "k1");
  ASSERT_TRUE(back);
  EXPECT_TRUE(back->solved);
  EXPECT_EQ(encode_pair_result(back->result), encode_pair_result(r));
  EXPECT_EQ(back->result.depth_source, "pieces");
  EXPECT_EQ(back->result.hull_depth, r.hull_depth);
  EXPECT_EQ(back->result.depth_bounds, r.depth_bounds);
  EXPECT_EQ(back->result.confirmed, r.confirmed);
  EXPECT_EQ(back->result.pieces, r.pieces);

  EXPECT_FALSE(read_cached_refinement(dir.string(), "k2"));  // absent
  // Another key's entry under this name is foreign.
  fs::copy_file(dir / "k1.pdr", dir / "k2.pdr");
  EXPECT_FALSE(read_cached_refinement(dir.string(), "k2"));
  // Truncated.
  fs::resize_file(dir / "k1.pdr", fs::file_size(dir / "k1.pdr") - 3);
  EXPECT_FALSE(read_cached_refinement(dir.string(), "k1"));
  // A checksum that matches a body that is no result.
  const std::string body = "1\nnot a result";
  std::ofstream(dir / "k3.pdr") << "pdcheck-refinement-2\nk3\n"
                                << content_hash(body) << "\n"
                                << body;
  EXPECT_FALSE(read_cached_refinement(dir.string(), "k3"));
  fs::remove_all(dir);
}
