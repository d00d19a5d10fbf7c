// Between the hull stage and the refinement: the convexity of the pieces auto
// mesh parts that a pair's verdict turns on, measured then and only then.
//
// A part's convexity decides only pairs whose hulls interfere beyond the
// tolerance: a pair with a nonconvex part is decided on the surfaces, one of
// two convex parts by its hulls. So a part is measured when such a pair has
// no part known to be nonconvex yet: first the part with more of those pairs
// (a bearing ring before its balls; the ring is nonconvex, and the balls'
// pairs are all refined whatever the balls are), then, where that part was
// convex, the other. Measured in `options.jobs` threads, from the convexity
// cache when it holds them. A pair the hull stage stopped early because its
// part might be refined (kAboveTolerance) and whose parts both turn out convex
// is solved on its hulls again; the others are noted and reported.
#pragma once

#include <functional>
#include <utility>
#include <vector>

#include "batch/run.h"
#include "results/pair_result.h"
#include "scene/parts.h"

namespace pd {

/// Whether the hull stage must hold `r` back from the report until its
/// parts' convexity is known (it may need the refinement).
bool may_need_refinement(const PairResult& r, const Part& a, const Part& b);

void measure_convexity_on_demand(std::vector<Part>& parts,
                                 const std::vector<std::pair<int, int>>& pairs,
                                 std::vector<PairResult>& results, const RunOptions& options,
                                 const std::function<PairChecks(int, int)>& checks);

}  // namespace pd
