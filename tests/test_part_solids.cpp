// Each part's distances built once for the convexity measures and the
// refinement (batch/part_solids.h).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "batch/pair_solve.h"
#include "batch/part_solids.h"
#include "batch/refine.h"
#include "corpus/cad_shapes.h"
#include "scene/part_convexity.h"
#include "scene/parts.h"
#include "scene/scene.h"
#include "scratch_dir.h"
#include "stl_file.h"

namespace {

using nlohmann::json;
using namespace pd;
namespace shapes = pd::shapes;

// One nonconvex bracket file, placed as it is and moved.
std::vector<Part> bracket_parts(const std::string& name) {
  const std::string dir = pd_test::scratch_dir("part_solids", name).string();
  const std::string file = dir + "/bracket.stl";
  pd::test::write_binary_stl(file, shapes::l_bracket(40, 5, 20));
  const json moved = {{1, 0, 0, 0.25}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  const json scene = {{"tolerance", 0.1},
                      {"parts",
                       {{{"id", "as_file"}, {"mesh", file}},
                        {{"id", "moved"}, {"mesh", file}, {"transform", moved}}}}};
  const SceneSpec spec = parse_scene_json(scene.dump(), "scene.json", "");
  std::vector<Part> parts = build_parts(spec, 1);
  for (const Part& p : parts) EXPECT_FALSE(p.error) << *p.error;
  return parts;
}

TEST(PartSolids, APartPlacedAsItsFileIsMeasuredWithTheDistancesTheRefinementUses) {
  const std::vector<Part> parts = bracket_parts("shared");
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_TRUE(placed_as_file(parts[0]));
  EXPECT_FALSE(placed_as_file(parts[1]));
  // Its surface is the file's mesh to the bit.
  const std::shared_ptr<const Mesh> placed = surface_mesh(parts[0]);
  const std::shared_ptr<const Mesh> file = file_mesh_of(*parts[0].surface);
  EXPECT_EQ(placed->vertices, file->vertices);
  EXPECT_EQ(placed->triangles, file->triangles);

  PartSolids solids(parts, size_t(64) << 20);
  int asked = 0;
  const auto prepared = [&](const Mesh& m) -> std::shared_ptr<const PreparedMesh> {
    ++asked;
    EXPECT_EQ(m.vertices, file->vertices);  // the file's mesh, as read
    const std::shared_ptr<const SolidDistance> d = solids.of(0, m);
    return {d, &d->mesh()};
  };
  const StoredConvexity shared = measure_file_convexity(parts[0], "", prepared);
  const StoredConvexity own = measure_file_convexity(parts[0], "");
  EXPECT_EQ(asked, 1);
  EXPECT_EQ(shared.concavity, own.concavity);  // the same bits
  EXPECT_EQ(shared.closed, own.closed);
  EXPECT_GT(shared.concavity, 0.1);
  // The refinement then finds the part's distances built.
  EXPECT_EQ(solids.builds(), 1u);
  EXPECT_EQ(solids.of(0).get(), solids.of(0).get());
  EXPECT_EQ(solids.builds(), 1u);
  // The moved part's are its own, of its placed surface.
  EXPECT_NEAR(solids.of(1)->box().min().x() - solids.of(0)->box().min().x(), 0.25, 1e-12);
  EXPECT_EQ(solids.builds(), 2u);
}

TEST(PartSolids, ABudgetTooSmallForAPartBuildsItAgainWhenAskedAgain) {
  const std::vector<Part> parts = bracket_parts("tiny_budget");
  PartSolids solids(parts, 1);
  EXPECT_TRUE(solids.of(0)->closed());
  EXPECT_TRUE(solids.of(1)->closed());  // the first, held by no one, makes room
  EXPECT_TRUE(solids.of(0)->closed());
  EXPECT_EQ(solids.builds(), 3u);
  EXPECT_GE(solids.drops(), 1u);
}

TEST(PartSolids, EachPartIsBuiltOnceForItsMeasureAndItsPairsAndLetGoAfter) {
  // Six plates in a row, each with a pin through its hole (clear of it), every
  // file placed as it is, and a budget for about three plates' distances. Each
  // plate is measured nonconvex (the pins never) with the distances its pair
  // is then refined with, and they go after its pair: each part is built
  // once, and no two plates' distances are held at once.
  const std::string dir = pd_test::scratch_dir("part_solids", "measure_order").string();
  json list = json::array();
  for (int k = 0; k < 6; ++k) {
    const Vec3 at(100.0 * k, 0, 0);
    const std::string plate = dir + "/plate" + std::to_string(k) + ".stl",
                      pin = dir + "/pin" + std::to_string(k) + ".stl";
    pd::test::write_binary_stl(plate,
                               shapes::translated(shapes::plate_with_hole(40, 6, 5, 768), at));
    pd::test::write_binary_stl(pin, shapes::translated(shapes::cylinder({0, 0}, 4, -5, 15, 8), at));
    list.push_back({{"id", "plate" + std::to_string(k)}, {"mesh", plate}});
    list.push_back({{"id", "pin" + std::to_string(k)}, {"mesh", pin}});
  }
  const json scene = {{"tolerance", 0.1}, {"parts", list}};
  std::vector<Part> parts = build_parts(parse_scene_json(scene.dump(), "scene.json", ""), 1);
  std::vector<std::pair<int, int>> pairs;
  for (int k = 0; k < 6; ++k) pairs.push_back({2 * k, 2 * k + 1});
  const std::function<PairChecks(int, int)> checks = [](int, int) { return PairChecks{}; };
  IpoptLocalSolver ipopt;
  std::vector<PairResult> results;
  for (auto [a, b] : pairs)
    results.push_back(
        solve_part_pair(a, parts[a], b, parts[b], SolverSettings{}, 0.1, ipopt, checks(a, b)));
  const size_t plate = solid_bytes(file_mesh_of(*parts[0].surface)->triangles.cols()),
               pin = solid_bytes(file_mesh_of(*parts[1].surface)->triangles.cols());
  ASSERT_LT(12 * pin, plate);  // the six pins fit in the half plate to spare
  PartSolids solids(parts, 3 * plate + plate / 2);
  RunOptions options;
  options.tolerance = 0.1;
  options.quiet = true;
  options.jobs = 1;
  refine_nonconvex_pairs(parts, pairs, results, options, checks, solids);
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(parts[size_t(2 * k)].convex, false) << k;
    EXPECT_FALSE(parts[size_t(2 * k + 1)].convex.has_value()) << k;
  }
  for (const PairResult& r : results) EXPECT_EQ(r.status, Status::kSeparated);
  EXPECT_EQ(solids.builds(), 6u + 6u);
  EXPECT_EQ(solids.drops(), 0u);
  EXPECT_LT(solids.peak_bytes(), plate + plate / 2);
}

}  // namespace
