// Between the hull stage and the refinement: the convexity of the pieces auto
// parts, mesh files and B-rep alike (Part::convexity_on_demand), measured
// where a pair's verdict turns on it and nowhere else.
//
// A part's convexity decides only pairs whose hulls interfere beyond the
// tolerance: such a pair with a nonconvex part is decided on the surfaces, one
// of convex parts by its hulls. Which parts a pair measures is a function of
// the pair alone (its hull verdict, its parts' sizes and convexities), never of
// the other pairs of the run, so a shard, a --reuse run and a full run measure
// alike for every pair they share (and report the same thing of it):
// - a pair that needs pieces (a clearance check, a `decompose` part): every
//   on-demand part, since each nonconvex one is decomposed;
// - a pair with a part already known nonconvex (decompose, or measured for
//   another pair): none;
// - otherwise its on-demand parts one by one, the likelier nonconvex first
//   (more vertices read per hull vertex: a bearing ring before its balls; the
//   ring is nonconvex and the balls' pairs are then decided on the surfaces
//   whatever the balls are), until one is nonconvex.
// Parts are measured in `options.jobs` threads, from the convexity cache when
// it holds them. A pair the hull stage stopped early because a part might be
// nonconvex (kAboveTolerance) and whose parts turn out convex is solved on its
// hulls again; then the held pairs are noted and reported.
#pragma once

#include <functional>
#include <utility>
#include <vector>

#include "batch/pair_solve.h"
#include "batch/part_solids.h"
#include "batch/run.h"
#include "results/pair_result.h"
#include "scene/parts.h"

namespace pd {

/// Whether the hull stage's result `r` (or one taken from an earlier report)
/// turns on the convexity of an on-demand part of a, b: the hull stage holds it
/// back from the report until that is measured.
bool turns_on_convexity(const PairResult& r, const Part& a, const Part& b);

/// A part placed as its file is measured with its distances from `solids`,
/// kept there for the refinement.
void measure_convexity_on_demand(std::vector<Part>& parts,
                                 const std::vector<std::pair<int, int>>& pairs,
                                 std::vector<PairResult>& results, const RunOptions& options,
                                 const std::function<PairChecks(int, int)>& checks,
                                 PartSolids& solids);

}  // namespace pd
