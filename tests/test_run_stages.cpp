// The stages of run_scene on their own (batch/run_stages.h): candidate pairs,
// reuse, and the owners they share (batch/broad_phase.h).
#include <gtest/gtest.h>

#include "batch/broad_phase.h"
#include "batch/run_stages.h"
#include "results/fingerprint.h"

using namespace pd;

namespace {

Part box_part(const std::string& id, double x0, double x1) {
  Part p;
  p.id = id;
  p.box.lo = Vec3(x0, 0, 0);
  p.box.hi = Vec3(x1, 1, 1);
  return p;
}

// a and b overlap; c is 3.5 from b and 4 from a; d could not be read.
std::vector<Part> four_parts() {
  std::vector<Part> parts = {box_part("a", 0, 1), box_part("b", 0.5, 1.5), box_part("c", 5, 6),
                             box_part("d", 0, 6)};
  parts[3].error = "cannot load mesh file d.stl";
  return parts;
}

using Pairs = std::vector<std::pair<int, int>>;

}  // namespace

TEST(RunStages, BroadPhaseCountsWhatItCulledAndWhatItCouldNotForm) {
  const CandidatePairs c = broad_phase_pairs(four_parts(), Checks{});
  EXPECT_EQ(c.pairs, (Pairs{{0, 1}}));
  EXPECT_EQ(c.all_pairs, 6);
  EXPECT_EQ(c.unchecked, 3);  // d's pairs
  EXPECT_EQ(c.culled, 2);     // a-c, b-c
}

TEST(RunStages, TheClearanceWidensTheBroadPhase) {
  Checks checks;
  checks.clearance = ClearanceCheck{};
  checks.clearance->min = 1.0;
  checks.clearance->pairs.push_back({"c", "a", 4.0});  // a pair's own reach counts for all
  EXPECT_EQ(broad_phase_reach(checks), 4.0);
  const CandidatePairs c = broad_phase_pairs(four_parts(), checks);
  EXPECT_EQ(c.pairs, (Pairs{{0, 1}, {0, 2}, {1, 2}}));  // touching at the reach counts
  EXPECT_EQ(c.culled, 0);
  std::vector<Part> parts = four_parts();
  const auto of = pair_checks_of(parts, checks);
  EXPECT_EQ(of(0, 2).clearance, 4.0);  // the named pair, in either order
  EXPECT_EQ(of(2, 0).clearance, 4.0);
  EXPECT_EQ(of(0, 1).clearance, 1.0);  // the scene's minimum
  EXPECT_EQ(of(0, 1).motion, nullptr);
}

TEST(RunStages, ListedPairsAreSortedOnce) {
  const CandidatePairs c = listed_pairs(four_parts(), {{"c", "a"}, {"b", "a"}, {"a", "c"}});
  EXPECT_EQ(c.pairs, (Pairs{{0, 1}, {0, 2}}));
  EXPECT_EQ(c.all_pairs, 2);
  EXPECT_EQ(c.culled, 0);
  EXPECT_EQ(c.unchecked, 0);
}

TEST(RunStages, WithoutAnEarlierReportEveryPairIsSolved) {
  const std::vector<Part> parts = four_parts();
  const Pairs pairs = {{0, 1}, {1, 2}};
  std::vector<PairResult> results(pairs.size());
  RunOptions options;
  int reported = 0;
  options.on_pair = [&](const PairResult&, const std::vector<Part>&) { ++reported; };
  EXPECT_EQ(reuse_results(parts, pairs, {"h0", "h1", "h2", "h3"}, "s", options, results),
            (std::vector<size_t>{0, 1}));
  EXPECT_EQ(reported, 0);
}

TEST(RunStages, AnUnchangedPairKeepsItsOldResult) {
  const std::vector<Part> parts = four_parts();
  const Pairs pairs = {{0, 1}, {1, 2}};
  PriorResults prior;
  prior.settings_hash = "s";
  prior.part_hash = {{"a", "h0"}, {"b", "h1"}, {"c", "old"}};
  PairResult old;
  old.status = Status::kInterference;
  old.depth = 0.25;
  old.method = "mlsl";
  prior.pairs[pair_fingerprint("a", "b")] = old;
  prior.pairs[pair_fingerprint("b", "c")] = old;  // c changed since: solved again
  RunOptions options;
  options.reuse = &prior;
  std::vector<const PairResult*> reported;
  std::vector<PairResult> results(pairs.size());
  options.on_pair = [&](const PairResult& r, const std::vector<Part>&) { reported.push_back(&r); };
  EXPECT_EQ(reuse_results(parts, pairs, {"h0", "h1", "h2", "h3"}, "s", options, results),
            (std::vector<size_t>{1}));
  EXPECT_TRUE(results[0].reused);
  EXPECT_EQ(results[0].a, 0);
  EXPECT_EQ(results[0].b, 1);
  EXPECT_EQ(results[0].depth, 0.25);
  ASSERT_EQ(reported.size(), 1u);
  EXPECT_EQ(reported[0], &results[0]);
  // Other settings: nothing stands.
  std::vector<PairResult> again(pairs.size());
  EXPECT_EQ(reuse_results(parts, pairs, {"h0", "h1", "h2", "h3"}, "t", options, again),
            (std::vector<size_t>{0, 1}));
}

TEST(BroadPhase, OneOwnerEachForCountsAxesAndBoxes) {
  EXPECT_EQ(pair_count(0), 0);
  EXPECT_EQ(pair_count(1), 0);
  EXPECT_EQ(pair_count(35), 595);
  EXPECT_EQ(widest_spread_axis({}), 0);
  Aabb a, b;
  b.lo = Vec3(1, 0, 5);
  b.hi = Vec3(2, 1, 7);
  EXPECT_EQ(widest_spread_axis({a, b}), 2);  // centres 0 and 6 apart along z
  const Part p = box_part("a", 0, 1);
  EXPECT_EQ(culling_box(p, Checks{}).hi, p.box.hi);
}
