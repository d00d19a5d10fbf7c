// Piece pairs combined in one place (batch/piece_pairs.h): the deepest overlap,
// else the closest gap, with the direction and pieces that realise it — for the
// static, clearance and motion checks; against exact per-piece references.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "batch/motion_sweep.h"
#include "batch/pair_solve.h"
#include "batch/piece_pairs.h"
#include "batch/run.h"
#include "box_points.h"
#include "geometry/hull.h"
#include "report/report_json.h"
#include "solve/exact.h"

using namespace pd;
using nlohmann::json;

namespace {

using pd_test::box_points;

Points octahedron(double r) {
  Points p(3, 6);
  p << r, -r, 0, 0, 0, 0, 0, 0, r, -r, 0, 0, 0, 0, 0, 0, r, -r;
  return p;
}

Part part_of(const std::vector<Points>& pieces) {
  Part p;
  for (const Points& x : pieces) {
    p.pieces.push_back(convex_hull(x));
    const Aabb b = Aabb::of(x);
    p.box = p.pieces.size() == 1 ? b : p.box.merged(b);
  }
  return p;
}

// An octahedron |x|+|y|+|z| <= 1 between two cubes on its diagonal: both piece
// boxes overlap its box, the first cube is 0.8/√3 away, the second 0.5/√3.
const Points kFarBox = box_points(Vec3::Constant(0.6), Vec3::Constant(1.6));
const Points kNear = box_points(Vec3::Constant(-1.5), Vec3::Constant(-0.5));

// Every point of `a` at or below every point of `b` along `dir` (to rounding):
// `dir` is a separating-plane normal from a to b.
bool separates(const Points& a, const Points& b, const Vec3& dir) {
  return (dir.transpose() * a).maxCoeff() <= (dir.transpose() * b).minCoeff() + 1e-9;
}

SolverSettings exact_method() {
  SolverSettings s;
  s.method = Method::kExact;
  return s;
}

}  // namespace

TEST(PiecePairs, CombineTakesTheDeepestOverlap) {
  std::vector<PieceOutcome> o = {make_outcome(0, 0, 0.0, Vec3::UnitX(), 0.3),
                                 make_outcome(0, 1, 0.2, Vec3::UnitY(), std::nullopt),
                                 make_outcome(1, 0, 0.7, -Vec3::UnitZ(), std::nullopt),
                                 make_outcome(1, 1, 0.7, Vec3::UnitZ(), std::nullopt)};
  o[1].stats.ipopt_calls = 2;
  o[3].stats.ipopt_calls = 5;
  const PiecePairsResult r = combine_piece_outcomes(o);
  EXPECT_EQ(r.depth, 0.7);
  EXPECT_EQ(r.direction, -Vec3::UnitZ());  // the first of equal depths
  EXPECT_EQ(r.piece_a, 1);
  EXPECT_EQ(r.piece_b, 0);
  EXPECT_FALSE(r.distance);
  EXPECT_EQ(r.stats.ipopt_calls, 7);
  EXPECT_EQ(r.solved, 4);
}

TEST(PiecePairs, CombineTakesTheSmallestKnownGap) {
  const PiecePairsResult r = combine_piece_outcomes({make_outcome(0, 0, 0.0, Vec3::UnitX(), 0.9),
                                                     make_outcome(1, 0, 0.0, Vec3::UnitY(), 0.4),
                                                     make_outcome(2, 0, 0.0, Vec3::UnitZ(), 1.2)});
  EXPECT_EQ(r.depth, 0.0);
  ASSERT_TRUE(r.distance);
  EXPECT_EQ(*r.distance, 0.4);
  EXPECT_EQ(r.direction, Vec3::UnitY());
  EXPECT_EQ(r.piece_a, 1);
  // A piece pair apart by an unknown distance may be the closest: no distance.
  const PiecePairsResult u = combine_piece_outcomes(
      {make_outcome(0, 0, 0.0, Vec3::UnitX(), 0.4), make_outcome(0, 1, 0.0, Vec3::UnitY(), {})});
  EXPECT_FALSE(u.distance);
  EXPECT_EQ(u.direction, Vec3::UnitY());
}

TEST(PiecePairs, BoxDisjointPairsAreSolvedOnlyWhileTheyCouldBeCloser) {
  // Three pieces of a at box gaps 2, 0.5 and 2 from b's one piece; the closest box
  // is 1.0 away when solved, so those at gap 2 cannot beat it and are not solved.
  const std::vector<Aabb> a = {{Vec3(3, 0, 0), Vec3(4, 1, 1)},
                               {Vec3(1.5, 0, 0), Vec3(2, 1, 1)},
                               {Vec3(-4, 0, 0), Vec3(-3, 1, 1)}};
  const std::vector<Aabb> b = {{Vec3(-1, 0, 0), Vec3(1, 1, 1)}};
  std::vector<int> asked;
  const PiecePairsResult r = solve_piece_pairs(a, b, [&](int i, int j) {
    asked.push_back(i);
    return make_outcome(i, j, 0.0, Vec3(i, 1, 0), i == 1 ? 1.0 : 2.5);
  });
  EXPECT_EQ(asked, std::vector<int>({1}));
  ASSERT_TRUE(r.distance);
  EXPECT_EQ(*r.distance, 1.0);
  EXPECT_EQ(r.direction, Vec3(1, 1, 0));
  // Unknown distances: one solve for a direction, the box-closest.
  asked.clear();
  solve_piece_pairs(a, b, [&](int i, int j) {
    asked.push_back(i);
    return make_outcome(i, j, 0.0, Vec3::UnitX(), std::nullopt);
  });
  EXPECT_EQ(asked, std::vector<int>({1}));
  // An overlapping box pair overlaps: the disjoint ones cannot matter.
  asked.clear();
  const std::vector<Aabb> b2 = {{Vec3(-1, 0, 0), Vec3(1.6, 1, 1)}};
  const PiecePairsResult o = solve_piece_pairs(a, b2, [&](int i, int j) {
    asked.push_back(i);
    return make_outcome(i, j, 0.1, Vec3::UnitX(), std::nullopt);
  });
  EXPECT_EQ(asked, std::vector<int>({1}));
  EXPECT_EQ(o.depth, 0.1);
}

TEST(PiecePairs, SeparatedPairReportsTheClosestPiecePairNotTheFirst) {
  // The case: with --method exact the first piece pair's distance was
  // reported (here 0.8/√3 ≈ 0.462) where the pair is 0.5/√3 ≈ 0.289 apart.
  const Part a = part_of({kFarBox, kNear});
  const Part b = part_of({octahedron(1.0)});
  IpoptLocalSolver ipopt;
  const PairResult r = solve_part_pair(0, a, 1, b, exact_method(), 0.1, ipopt);
  EXPECT_EQ(r.status, Status::kSeparated);
  const double near = *exact_depth(kNear, octahedron(1.0)).distance;
  EXPECT_NEAR(near, 0.5 / std::sqrt(3.0), 1e-12);
  ASSERT_TRUE(r.distance);
  EXPECT_NEAR(*r.distance, near, 1e-12);
  EXPECT_TRUE(separates(kNear, octahedron(1.0), r.direction));
  // The clearance check's distance is the same smallest one.
  const PairResult c =
      solve_part_pair(0, a, 1, b, SolverSettings{}, 0.1, ipopt, {1.0, nullptr, std::nullopt});
  EXPECT_EQ(c.status, Status::kClearanceViolation);
  ASSERT_TRUE(c.distance);
  EXPECT_NEAR(*c.distance, near, 1e-8);
  EXPECT_TRUE(separates(kNear, octahedron(1.0), c.direction));
}

TEST(PiecePairs, EveryPiecePairSkippedStillGivesASeparatingDirection) {
  // Part boxes overlap, piece boxes do not: the old loop skipped every piece pair
  // and reported +z, which separates nothing here.
  const Points right = box_points(Vec3(2, -0.5, -0.5), Vec3(3, 0.5, 0.5));
  const Points left = box_points(Vec3(-3, -0.5, -0.5), Vec3(-2.2, 0.5, 0.5));
  const Part a = part_of({left, right});
  const Part b = part_of({octahedron(1.0)});
  IpoptLocalSolver ipopt;
  for (const SolverSettings& s : {exact_method(), SolverSettings{}}) {
    const PairResult r = solve_part_pair(0, a, 1, b, s, 0.1, ipopt);
    EXPECT_EQ(r.status, Status::kSeparated) << r.method;
    EXPECT_TRUE(separates(right, octahedron(1.0), r.direction)) << r.method;
    if (s.method == Method::kExact) {
      ASSERT_TRUE(r.distance);
      EXPECT_NEAR(*r.distance, 1.0, 1e-12);
      EXPECT_NEAR(r.direction.x(), -1.0, 1e-9);  // from a's right piece to b
    }
  }
}

TEST(PiecePairs, MotionSweepTakesTheClosestPiecePair) {
  Part a = part_of({kFarBox, kNear});
  const Part b = part_of({octahedron(1.0)});
  a.motion = RigidMotion{};  // at rest: every step is the static pair
  MotionCheck m;
  m.grid = {0, 1, 1};
  IpoptLocalSolver ipopt;
  const MotionSweep sw = sweep_pair(a, b, m, SolverSettings{}, ipopt);
  ASSERT_TRUE(sw.trace.min_distance);
  EXPECT_NEAR(*sw.trace.min_distance, 0.5 / std::sqrt(3.0), 1e-8);
  EXPECT_TRUE(separates(kNear, octahedron(1.0), sw.direction_at_max));
}

TEST(PiecePairs, ExactSceneWithMeshPiecesReportsTheSmallestDistance) {
  // The same through a scene: a two-object OBJ as pieces "meshes", --method exact.
  const std::string obj =
      testing::TempDir() + "piece_pairs_two_cubes_" + std::to_string(getpid()) + ".obj";
  {
    std::ofstream f(obj);
    int base = 0;
    for (const Points* p : {&kFarBox, &kNear}) {
      f << "o piece" << base / 8 << "\n";
      for (int k = 0; k < 8; ++k)
        f << "v " << p->col(k).x() << " " << p->col(k).y() << " " << p->col(k).z() << "\n";
      const int faces[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
      for (const auto& t : faces)
        f << "f " << base + t[0] + 1 << " " << base + t[1] + 1 << " " << base + t[2] + 1 << "\n";
      base += 8;
    }
  }
  json oct = json::array();
  for (int k = 0; k < 6; ++k) {
    const Vec3 v = octahedron(1.0).col(k);
    oct.push_back({v.x(), v.y(), v.z()});
  }
  const json scene = {
      {"tolerance", 0.1},
      {"solver", {{"method", "exact"}}},
      {"parts",
       {{{"id", "a"}, {"mesh", obj}, {"pieces", "meshes"}}, {{"id", "b"}, {"vertices", oct}}}}};
  const SceneSpec spec = parse_scene_json(scene.dump(), "test.json", ".");
  RunOptions o;
  o.tolerance = 0.1;
  o.quiet = true;
  spec.solver.apply(o.solver);
  const RunResult r = run_scene(spec, o);
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_EQ(r.parts[0].pieces.size(), 2u);
  EXPECT_EQ(r.pairs[0].status, Status::kSeparated);
  ASSERT_TRUE(r.pairs[0].distance);
  EXPECT_NEAR(*r.pairs[0].distance, 0.5 / std::sqrt(3.0), 1e-9);
}
