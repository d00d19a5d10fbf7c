// The nonconvex refinement (batch/refine.h): which pairs it takes, its two
// pure decisions on hand-made brackets (decide_refined from the pieces and the
// deepest vertex, decide_thickness from the overlap thickness), and the whole
// refinement in process on an L-bracket (legs 5 thick, inner corner at (5, 5))
// and blocks in its notch whose overlap is known by construction.
#include <gtest/gtest.h>

#include <memory>

#include "batch/refine.h"
#include "box_points.h"
#include "corpus/cad_shapes.h"
#include "geometry/hull.h"
#include "geometry/solid_distance.h"
#include "inline_part.h"

using namespace pd;
using Outcome = ThicknessResult::Outcome;

namespace {

// A mesh part as build_parts makes it under pieces auto: its hull, and its
// surface when measured nonconvex.
Part mesh_part(const std::string& id, const Mesh& m, bool convex) {
  Part p;
  p.id = id;
  p.source = id + ".stl";
  p.pieces.push_back(convex_hull(m.vertices));
  p.box = Aabb::of(p.pieces[0].vertices);
  p.mode = Pieces::kAuto;
  p.convex = convex;
  PartSurface s;
  s.file_mesh = std::make_shared<const Mesh>(m);
  s.file_hash = id;
  s.closed = true;
  p.surface = std::move(s);
  return p;
}

PairResult hull_result(double depth) {
  PairResult r;
  r.status = Status::kInterference;
  r.depth = depth;
  r.at = Vec3(9, 9, 9);
  return r;
}

// A mesh verdict whose surfaces meet, the deepest vertex `depth` along +y.
MeshVerdict meeting(double vertex_depth) {
  MeshVerdict m;
  m.intersect = true;
  m.vertex_depth = vertex_depth;
  m.vertex_direction = Vec3::UnitY();
  m.vertex_at = Vec3(1, 2, 3);
  return m;
}

ThicknessResult bracket(Outcome o, double lower, double upper, double resolution = 0.001) {
  ThicknessResult t;
  t.outcome = o;
  t.lower = lower;
  t.upper = upper;
  t.resolution = resolution;
  t.at = Vec3(4, 5, 6);
  t.direction = Vec3::UnitX();
  t.evaluations = 1234;
  return t;
}

PairResult thickness(const MeshVerdict& m, const ThicknessResult& t) {
  return decide_thickness(hull_result(3.0), m, t, 0.05, 1.0, "b: open surface");
}

}  // namespace

TEST(Refine, OnlyHullInterferencesOfARefinablePartAreRefined) {
  const Part bracket = mesh_part("bracket", shapes::l_bracket(40, 5, 20), false);
  const Part block = mesh_part("block", shapes::box(Vec3(6, 6, 2), Vec3(25, 25, 18)), true);
  ASSERT_TRUE(bracket.refinable());
  ASSERT_FALSE(block.refinable());
  PairResult r = hull_result(3.0);
  EXPECT_TRUE(needs_refinement(r, bracket, block));
  EXPECT_TRUE(needs_refinement(r, block, bracket));
  EXPECT_FALSE(needs_refinement(r, block, block));
  r.motion = MotionTrace{};  // motion pairs are not refined
  EXPECT_FALSE(needs_refinement(r, bracket, block));
  r.motion.reset();
  r.status = Status::kFalsePositive;
  EXPECT_FALSE(needs_refinement(r, bracket, block));
  // The hull bounds the parts' depth from above: a final hull result is confirmed.
  note_hull_stage(r, bracket, block);
  EXPECT_EQ(r.confirmed, true);
  r = hull_result(3.0);
  note_hull_stage(r, bracket, block);  // still to refine: nothing said yet
  EXPECT_FALSE(r.confirmed);
  r.status = Status::kSeparated;
  note_hull_stage(r, block, block);  // parts that may be nonconvex: the hulls hold them
  EXPECT_EQ(r.confirmed, true);
  r = hull_result(3.0);
  note_hull_stage(r, block, block);  // convex parts: their depth is the hulls'
  EXPECT_EQ(r.confirmed, true);
  r = hull_result(3.0);
  r.motion = MotionTrace{};  // swept on the hulls of a nonconvex part
  note_hull_stage(r, bracket, block);
  EXPECT_EQ(r.confirmed, false);
  Part hull_only = block;  // pieces hull: the hull is the part, nothing to confirm
  hull_only.mode = Pieces::kHull;
  hull_only.surface.reset();
  r = hull_result(3.0);
  note_hull_stage(r, hull_only, hull_only);
  EXPECT_FALSE(r.confirmed);
  r.status = Status::kError;
  note_hull_stage(r, bracket, block);
  EXPECT_FALSE(r.confirmed);
}

TEST(Refine, DecideRefinedNeverQuietlyPassesAnUndecidedPair) {
  PairResult hull;
  hull.status = Status::kInterference;
  hull.depth = 3.0;
  MeshVerdict m;
  m.intersect = true;
  m.vertex_depth = 0.01;
  PairResult pieces;
  pieces.status = Status::kFalsePositive;
  pieces.depth = 0.02;
  pieces.pieces = {{2, 0}};
  // Complete decompositions: the pieces decide.
  PairResult r = decide_refined(hull, m, &pieces, true, 0.05, 1.0);
  EXPECT_EQ(r.status, Status::kFalsePositive);
  EXPECT_EQ(r.depth_source, "pieces");
  EXPECT_EQ(*r.hull_depth, 3.0);
  EXPECT_EQ((*r.depth_bounds)[0], 0.01);
  EXPECT_EQ((*r.depth_bounds)[1], 3.0);
  EXPECT_TRUE(*r.confirmed);
  // A decomposition past its time box: nothing decides, the pair is flagged.
  r = decide_refined(hull, m, &pieces, false, 0.05, 1.0);
  EXPECT_EQ(r.status, Status::kInterference);
  EXPECT_FALSE(*r.confirmed);
  // ... unless the vertex bound alone exceeds the tolerance.
  m.vertex_depth = 0.2;
  r = decide_refined(hull, m, &pieces, false, 0.05, 1.0);
  EXPECT_EQ(r.status, Status::kInterference);
  EXPECT_TRUE(*r.confirmed);
  EXPECT_EQ(r.depth_source, "vertex");
  EXPECT_EQ(r.depth, 0.2);
  // Meshes apart: separated, whatever the hulls said.
  m.intersect = false;
  r = decide_refined(hull, m, nullptr, true, 0.05, 1.0);
  EXPECT_EQ(r.status, Status::kSeparated);
  EXPECT_EQ(r.depth_source, "mesh-test");
  EXPECT_EQ(r.depth, 0.0);
}

TEST(Refine, DecideRefinedTakesThePiecesErrorsAndTheirClearance) {
  const PairResult hull = hull_result(3.0);
  PairResult pieces;
  pieces.status = Status::kError;
  pieces.error = "worker crashed (Aborted)";
  const PairResult lost = decide_refined(hull, meeting(0.01), &pieces, true, 0.05, 1.0);
  EXPECT_EQ(lost.status, Status::kError);
  EXPECT_EQ(lost.error, "piece pairs: worker crashed (Aborted)");
  // Meshes apart, a clearance measured over the pieces: its violation stands.
  MeshVerdict apart;
  apart.intersect = false;
  pieces = PairResult{};
  pieces.status = Status::kClearanceViolation;
  pieces.distance = 0.3;
  pieces.direction = Vec3::UnitX();
  pieces.at = Vec3(7, 7, 7);
  const PairResult r = decide_refined(hull, apart, &pieces, true, 0.05, 1.0);
  EXPECT_EQ(r.status, Status::kClearanceViolation);
  EXPECT_EQ(r.depth, 0.0);
  EXPECT_EQ(r.distance, 0.3);
  EXPECT_EQ(r.direction, Vec3::UnitX());
  EXPECT_EQ(r.at, Vec3(7, 7, 7));
  EXPECT_EQ(r.margin, 0.05);
  // A vertex bound equal to the hull depth: no bracket to show.
  EXPECT_FALSE(decide_refined(hull, meeting(3.0), nullptr, true, 0.05, 1.0).depth_bounds);
}

TEST(Refine, DecideThicknessSaysWhatTheBracketProves) {
  // Above the tolerance: an interference at the thickest ball, bracketed below
  // the hull depth.
  // The depth is the number with the fewest digits the bracket holds.
  PairResult r = thickness(meeting(0.01), bracket(Outcome::kAbove, 0.2, 0.4));
  EXPECT_EQ(r.status, Status::kInterference);
  EXPECT_EQ(r.depth_source, "thickness");
  EXPECT_EQ(r.depth, 0.3);
  EXPECT_EQ(r.direction, Vec3::UnitX());
  EXPECT_EQ(r.depth_bounds, (std::array<double, 2>{0.2, 0.4}));
  EXPECT_EQ(r.hull_depth, 3.0);
  EXPECT_EQ(r.at, Vec3(4, 5, 6));
  EXPECT_EQ(r.confirmed, true);
  EXPECT_EQ(r.margin, 0.05 - 0.3);
  r = thickness(meeting(0.01), bracket(Outcome::kAbove, 0.999849, 1.0084));
  EXPECT_EQ(r.depth, 1.0);
  EXPECT_EQ(r.depth_bounds, (std::array<double, 2>{0.999849, 1.0084}));
  EXPECT_EQ(thickness(meeting(0.01), bracket(Outcome::kAbove, 0.2, 5)).depth_bounds,
            (std::array<double, 2>{0.2, 3.0}));
  // Below: a false positive when an overlap above the coordinates' resolution
  // was found (its depth > 0), separated when the upper bound is within it.
  r = thickness(meeting(0.01), bracket(Outcome::kBelow, 0.011, 0.013));
  EXPECT_EQ(r.status, Status::kFalsePositive);
  EXPECT_EQ(r.depth, 0.012);
  EXPECT_EQ(r.confirmed, true);
  EXPECT_TRUE(r.reason.empty());
  r = thickness(meeting(0.0), bracket(Outcome::kBelow, 0.0, 1e-13));
  EXPECT_EQ(r.status, Status::kSeparated);
  EXPECT_FALSE(r.at);
  r = thickness(meeting(0.0007), bracket(Outcome::kBelow, 0.0005, 0.0009));
  EXPECT_EQ(r.status, Status::kSeparated);
  EXPECT_EQ(r.depth, 0.0);
  EXPECT_EQ(r.depth_bounds, (std::array<double, 2>{0.0005, 0.0009}));
  // The work ran out while narrowing: no overlap shown, the upper bound is the depth.
  r = thickness(meeting(0.01), bracket(Outcome::kBelow, 0.0, 0.03));
  EXPECT_EQ(r.status, Status::kFalsePositive);
  EXPECT_EQ(r.depth, 0.03);
  EXPECT_FALSE(r.reason.empty());
  EXPECT_EQ(r.at, Vec3(1, 2, 3));  // no common interior point: the deepest surface point
  // A surface point deeper than the tolerance but within the resolution is no clash.
  r = thickness(meeting(0.08), bracket(Outcome::kBelow, 0.0, 0.09, 0.1));
  EXPECT_EQ(r.status, Status::kSeparated);
  EXPECT_EQ(r.depth_source, "thickness");
  // A thin part pushed deep: the deepest surface point decides.
  r = thickness(meeting(0.2), bracket(Outcome::kBelow, 0.01, 0.03));
  EXPECT_EQ(r.status, Status::kInterference);
  EXPECT_EQ(r.depth_source, "surface");
  EXPECT_EQ(r.depth, 0.2);
  EXPECT_EQ(r.direction, Vec3::UnitY());
  EXPECT_EQ(r.depth_bounds, (std::array<double, 2>{0.2, 3.0}));
  EXPECT_EQ(r.at, Vec3(1, 2, 3));
}

TEST(Refine, DecideThicknessLeavesAnOpenBracketUndecidedAndSaysWhy) {
  for (Outcome o : {Outcome::kBudget, Outcome::kTime}) {
    const PairResult r = thickness(meeting(0.01), bracket(o, 0.03, 0.08));
    EXPECT_EQ(r.status, Status::kUndecided);
    EXPECT_EQ(r.confirmed, false);
    EXPECT_EQ(r.depth, 0.03);
    EXPECT_EQ(r.reason, std::string(o == Outcome::kTime ? "time box" : "work budget") +
                            " reached after 1234 distance evaluations with the bracket still "
                            "around the tolerance");
  }
  // No closed solid: only the surfaces are known.
  const PairResult r = thickness(meeting(0.01), bracket(Outcome::kNoInside, 0, 0));
  EXPECT_EQ(r.status, Status::kUndecided);
  EXPECT_EQ(r.depth_source, "surface");
  EXPECT_EQ(r.depth, 0.01);
  EXPECT_EQ(r.depth_bounds, (std::array<double, 2>{0.01, 3.0}));
  EXPECT_EQ(r.at, Vec3(1, 2, 3));
  EXPECT_EQ(r.reason,
            "b: open surface: only the surfaces' meeting and the deepest surface point are known");
}

TEST(Refine, BlocksInAnLBracketsNotchAreDecidedWhereTheyMeet) {
  // Blocks in the notch: 1 clear of both legs, pushed 0.3 into the upright leg
  // (a 0.3 slab), pushed 0.05 into it; then a convex pair, never refined.
  std::vector<Part> parts = {
      mesh_part("bracket", shapes::l_bracket(40, 5, 20), false),
      mesh_part("clear", shapes::box(Vec3(6, 6, 2), Vec3(25, 25, 18)), true),
      mesh_part("deep", shapes::box(Vec3(4.7, 5, 2), Vec3(25, 25, 18)), true),
      mesh_part("shallow", shapes::box(Vec3(4.95, 5, 2), Vec3(25, 25, 18)), true),
      pd_test::inline_part("cube", pd_test::box_points(Vec3(20, 20, 10), Vec3(30, 30, 20)))};
  const std::vector<std::pair<int, int>> pairs = {{0, 1}, {0, 2}, {0, 3}, {1, 4}};
  RunOptions options;
  options.tolerance = 0.1;
  options.quiet = true;
  int told = 0;
  options.on_pair = [&](const PairResult&, const std::vector<Part>&) { ++told; };
  const std::function<PairChecks(int, int)> checks = [](int, int) { return PairChecks{}; };
  IpoptLocalSolver ipopt;
  std::vector<PairResult> results;
  for (const auto& [a, b] : pairs)
    results.push_back(
        solve_part_pair(a, parts[a], b, parts[b], SolverSettings{}, 0.1, ipopt, checks(a, b)));
  for (const PairResult& r : results) ASSERT_EQ(r.status, Status::kInterference);
  const PairResult convex = results[3];
  refine_nonconvex_pairs(parts, pairs, results, options, checks);
  // Each pair is told once: the three refined, and the convex pair the hull
  // stage held back while its parts' convexity was open.
  EXPECT_EQ(told, 4);
  // Clear of the legs: the hulls overlap, the surfaces do not meet.
  EXPECT_EQ(results[0].status, Status::kSeparated);
  EXPECT_EQ(results[0].depth_source, "mesh-test");
  EXPECT_EQ(results[0].depth, 0.0);
  EXPECT_EQ(results[0].confirmed, true);
  EXPECT_GT(*results[0].hull_depth, 1.0);
  // The slab: its thickness brackets 0.3.
  EXPECT_EQ(results[1].status, Status::kInterference);
  EXPECT_EQ(results[1].depth_source, "thickness");
  ASSERT_TRUE(results[1].depth_bounds);
  EXPECT_LE((*results[1].depth_bounds)[0], 0.3 + 1e-9);
  EXPECT_GE((*results[1].depth_bounds)[1], 0.3 - 1e-9);
  EXPECT_GT((*results[1].depth_bounds)[0], 0.1);
  EXPECT_EQ(results[1].confirmed, true);
  ASSERT_TRUE(results[1].at);
  EXPECT_GE(results[1].at->x(), 4.7 - 1e-9);
  EXPECT_LE(results[1].at->x(), 5 + 1e-9);
  // 0.05 into the leg: below the tolerance 0.1.
  EXPECT_EQ(results[2].status, Status::kFalsePositive);
  EXPECT_LE((*results[2].depth_bounds)[1], 0.1);
  EXPECT_GE((*results[2].depth_bounds)[1], 0.05 - 1e-9);
  // No nonconvex part: as the hull stage left it.
  EXPECT_EQ(results[3].status, convex.status);
  EXPECT_EQ(results[3].depth, convex.depth);
  EXPECT_EQ(results[3].depth_source, "hull");
  EXPECT_FALSE(results[3].hull_depth);
}

TEST(Refine, ReadsSurfacesFromTheStoreAndDecidesAlikeUnderAnyBudget) {
  // The parts stage keeps no surface: the refinement reads each from the mesh
  // store, and the memory budget decides only what it keeps between pairs,
  // never a result. Four blocks around a bracket's leg, each pair refined.
  const auto store = MeshStore::temporary();
  std::vector<Part> parts = {mesh_part("bracket", shapes::l_bracket(40, 5, 20), false)};
  for (int k = 0; k < 4; ++k)
    parts.push_back(
        mesh_part("block" + std::to_string(k),
                  shapes::box(Vec3(4.7 - 0.1 * k, 5 + 8 * k, 2), Vec3(25, 11 + 8 * k, 18)), true));
  for (Part& p : parts) {
    const Mesh& m = *p.surface->file_mesh;
    ASSERT_EQ(store->put(p.id, m), "");
    p.surface->stored = StoredMesh{store, p.id};
    p.surface->file_mesh.reset();
  }
  std::vector<std::pair<int, int>> pairs;
  for (int k = 1; k < 5; ++k) pairs.push_back({0, k});
  const std::function<PairChecks(int, int)> checks = [](int, int) { return PairChecks{}; };
  IpoptLocalSolver ipopt;
  std::vector<std::vector<PairResult>> runs;
  for (double memory : {0.0, 1024.0})
    for (int jobs : {1, 2}) {
      RunOptions options;
      options.tolerance = 0.1;
      options.quiet = true;
      options.memory_mb = memory;
      options.jobs = jobs;
      std::vector<PairResult> results;
      for (auto [a, b] : pairs)
        results.push_back(
            solve_part_pair(a, parts[a], b, parts[b], SolverSettings{}, 0.1, ipopt, checks(a, b)));
      refine_nonconvex_pairs(parts, pairs, results, options, checks);
      runs.push_back(results);
    }
  for (size_t k = 0; k < pairs.size(); ++k) {
    EXPECT_EQ(runs[0][k].depth_source, "thickness") << k;
    EXPECT_EQ(runs[0][k].status, Status::kInterference) << k;
    for (size_t r = 1; r < runs.size(); ++r) {
      EXPECT_EQ(runs[r][k].status, runs[0][k].status) << r << " " << k;
      EXPECT_EQ(runs[r][k].depth, runs[0][k].depth) << r << " " << k;
      EXPECT_EQ(runs[r][k].depth_bounds, runs[0][k].depth_bounds) << r << " " << k;
      EXPECT_EQ(runs[r][k].depth_source, runs[0][k].depth_source) << r << " " << k;
    }
  }
  // A surface gone from the store leaves the pair to its convex pieces: never a crash.
  parts[0].surface->stored->key = "gone";
  RunOptions options;
  options.tolerance = 0.1;
  options.quiet = true;
  std::vector<PairResult> results = {
      solve_part_pair(0, parts[0], 1, parts[1], SolverSettings{}, 0.1, ipopt, checks(0, 1))};
  refine_nonconvex_pairs(parts, {{0, 1}}, results, options, checks);
  EXPECT_NE(results[0].depth_source, "thickness");
}
