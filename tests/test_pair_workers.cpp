// The worker pool of pair solves (batch/pair_workers.h) on four small parts:
// each answer is the in-process solve_part_pair's, decoded in the parent; the
// costliest pair (by hull vertex counts) goes first; only the asked pairs run,
// with their own checks; a worker that crashes costs its pair only.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>

#include "batch/pair_workers.h"
#include "box_points.h"
#include "inline_part.h"

using namespace pd;
using pd_test::box_points;
using pd_test::inline_part;

namespace {

Points tetrahedron(const Vec3& at) {
  Points t(3, 4);
  t << 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1;
  return t.colwise() + at;
}

// Parts 0 and 1: boxes of 8 vertices overlapping by 0.1; parts 2 and 3:
// tetrahedra, 2 from the cube's centre out, 3 apart from 2 by 0.5 along x.
const std::vector<Part> kParts = {
    inline_part("cube", box_points(Vec3::Zero(), Vec3::Ones())),
    inline_part("box", box_points(Vec3(0.9, 0.2, 0.3), Vec3(1.9, 0.8, 0.7))),
    inline_part("tet", tetrahedron(Vec3(0.5, 0.5, 0.5))),
    inline_part("far", tetrahedron(Vec3(2, 0, 0)))};

// The pool's jobs: costs 4·4 = 16 (tet, far), 8·4 = 32 (cube, tet), 8·8 = 64.
const std::pair<int, int> kPairs[] = {{2, 3}, {0, 2}, {0, 1}};

PairJob job(size_t k) {
  const auto [a, b] = kPairs[k];
  return {a, b, &kParts[a], &kParts[b]};
}

RunOptions options(int jobs) {
  RunOptions o;
  o.tolerance = 0.05;
  o.jobs = jobs;
  o.quiet = true;
  return o;
}

// A clearance of 1 on the apart tetrahedra only.
PairChecks checks(int a, int b) {
  PairChecks c;
  if (a == 2 && b == 3) c.clearance = 1.0;
  return c;
}

struct Answers {
  std::vector<size_t> order;
  std::map<size_t, PairResult> results;
};

Answers run(const std::vector<size_t>& which, int jobs,
            const std::function<void(size_t)>& before_task = {}) {
  Answers out;
  solve_pairs_in_workers(
      which, job, options(jobs), checks, "pairs",
      [&](size_t k, PairResult r) {
        out.order.push_back(k);
        out.results.emplace(k, std::move(r));
      },
      before_task);
  return out;
}

void expect_solved_in_process(const Answers& got) {
  IpoptLocalSolver ipopt;
  for (const auto& [k, r] : got.results) {
    SCOPED_TRACE(k);
    const auto [a, b] = kPairs[k];
    const PairResult want =
        solve_part_pair(a, kParts[a], b, kParts[b], SolverSettings{}, 0.05, ipopt, checks(a, b));
    EXPECT_EQ(r.a, a);
    EXPECT_EQ(r.b, b);
    EXPECT_EQ(r.status, want.status);
    EXPECT_EQ(r.depth, want.depth);
    EXPECT_EQ(r.direction, want.direction);
    EXPECT_EQ(r.distance, want.distance);
    EXPECT_EQ(r.clearance_min, want.clearance_min);
    EXPECT_EQ(r.at, want.at);
  }
}

}  // namespace

TEST(PairWorkers, EachAnswerIsTheInProcessSolveCostliestFirst) {
  const Answers got = run({0, 1, 2}, 1);
  EXPECT_EQ(got.order, (std::vector<size_t>{2, 1, 0}));
  ASSERT_EQ(got.results.size(), 3u);
  expect_solved_in_process(got);
  // What each pair is, by construction.
  EXPECT_EQ(got.results.at(2).status, Status::kInterference);
  EXPECT_NEAR(got.results.at(2).depth, 0.1, 1e-12);
  EXPECT_EQ(got.results.at(1).status, Status::kInterference);
  EXPECT_EQ(got.results.at(0).status, Status::kClearanceViolation);
  EXPECT_NEAR(*got.results.at(0).distance, 0.5, 1e-9);
  EXPECT_EQ(got.results.at(0).clearance_min, 1.0);
}

TEST(PairWorkers, OnlyTheAskedPairsRunInAnyNumberOfWorkers) {
  const Answers got = run({2, 0}, 2);
  ASSERT_EQ(got.results.size(), 2u);
  EXPECT_TRUE(got.results.count(0) && got.results.count(2));
  expect_solved_in_process(got);
  EXPECT_TRUE(run({}, 1).results.empty());
}

TEST(PairWorkers, ACrashedWorkerCostsItsPairOnly) {
  const Answers got = run({0, 1, 2}, 1, [](size_t k) {
    if (k == 1) std::abort();
  });
  ASSERT_EQ(got.results.size(), 3u);
  const PairResult& lost = got.results.at(1);
  EXPECT_EQ(lost.status, Status::kError);
  EXPECT_EQ(lost.a, 0);
  EXPECT_EQ(lost.b, 2);
  EXPECT_EQ(lost.method, "mlsl");
  EXPECT_EQ(lost.error.rfind("worker crashed (", 0), 0u) << lost.error;
  EXPECT_EQ(got.results.at(0).status, Status::kClearanceViolation);
  EXPECT_EQ(got.results.at(2).status, Status::kInterference);
}
