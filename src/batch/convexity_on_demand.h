// Between the hull stage and the refinement: the convexity of the pieces auto
// parts, mesh files and B-rep alike (Part::convexity_on_demand), measured
// where a pair's verdict turns on it and nowhere else, pair by pair as the
// refinement reaches them (batch/refine.h): a part is measured with the
// distances its pairs are then refined with, built once and let go after its
// last pair.
//
// A part's convexity decides only pairs whose hulls interfere beyond the
// tolerance: such a pair with a nonconvex part is decided on the surfaces, one
// of convex parts by its hulls. Which parts a pair measures is a function of
// the pair alone (its hull verdict, its parts' sizes and their convexity known
// before any pair measured), never of the other pairs of the run, so a shard,
// a --reuse run and a full run measure alike for every pair they share (and
// report the same thing of it):
// - a pair that needs pieces (a clearance check, a `decompose` part): every
//   on-demand part, since each nonconvex one is decomposed;
// - a pair with a part known nonconvex from the start (decompose): none;
// - otherwise its on-demand parts one by one, the likelier nonconvex first
//   (more vertices read per hull vertex: a bearing ring before its balls; the
//   ring is nonconvex and the balls' pairs are then decided on the surfaces
//   whatever the balls are), until one is nonconvex.
// Each file at each stretch is measured once (its instances share the
// answer), from the convexity cache when it holds it. When every pair is
// settled, a pair the hull stage stopped early because a part might be
// nonconvex (kAboveTolerance) and whose parts turn out convex is solved on its
// hulls again; then the held pairs are noted and reported.
#pragma once

#include <functional>
#include <future>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "batch/pair_solve.h"
#include "batch/part_solids.h"
#include "batch/run.h"
#include "results/pair_result.h"
#include "scene/convexity_cache.h"
#include "scene/parts.h"

namespace pd {

/// Whether the hull stage's result `r` (or one taken from an earlier report)
/// turns on the convexity of an on-demand part of a, b: the hull stage holds it
/// back from the report until that is measured.
bool turns_on_convexity(const PairResult& r, const Part& a, const Part& b);

/// A pair's two parts' convexity as the pair knows it once settled: known
/// from the start, or measured for it (unset: neither).
struct PairConvexity {
  std::optional<bool> a, b;
};

/// The run's on-demand convexities. The parts are not changed until finish().
class ConvexityOnDemand {
 public:
  /// `parts`, `pairs`, `results` and `solids` outlive this.
  ConvexityOnDemand(std::vector<Part>& parts, const std::vector<std::pair<int, int>>& pairs,
                    const std::vector<PairResult>& results,
                    const std::function<PairChecks(int, int)>& checks, const std::string& cache_dir,
                    PartSolids& solids);

  /// Pair k's verdict turns on a convexity (turns_on_convexity).
  bool open(size_t k) const { return open_[k] != 0; }

  /// Measures what pair k turns on (any thread; a file another thread is
  /// measuring is waited for). A part placed as its file is measured with its
  /// distances from the PartSolids, where the refinement then finds them.
  PairConvexity settle(size_t k);

  /// After every open pair is settled: each measured part gets its convexity
  /// (a part that could not be measured, its surface lost from the store, is
  /// nonconvex: the refinement decides its pairs and reports what it cannot
  /// read); the pairs stopped early whose parts are convex are solved on their
  /// hulls again; the open pairs the refinement leaves are noted and reported.
  void finish(std::vector<PairResult>& results, const RunOptions& options);

 private:
  // Part p's convexity, measured once per file and stretch.
  bool measured_convex(int p);

  std::vector<Part>& parts_;
  const std::vector<std::pair<int, int>>& pairs_;
  const std::function<PairChecks(int, int)>& checks_;
  std::string cache_dir_;
  PartSolids& solids_;
  std::vector<char> open_;  ///< per pair
  std::mutex mutex_;
  std::vector<char> measured_;  ///< per part: some pair measured it
  std::map<std::string, std::shared_future<std::optional<StoredConvexity>>> by_file_;
};

}  // namespace pd
