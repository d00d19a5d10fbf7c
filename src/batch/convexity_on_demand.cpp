#include "batch/convexity_on_demand.h"

#include <algorithm>

#include "batch/refine.h"
#include "batch/run_stages.h"
#include "parallel_for.h"
#include "scene/part_convexity.h"

namespace pd {

namespace {

bool unmeasured_or_refinable(const Part& p) {
  return p.refinable() || convexity_unmeasured(p);
}

// The hull stage flagged the pair (its verdict may need the parts) and no part
// is known to be nonconvex: a part's convexity decides it.
bool open(const PairResult& r, const Part& a, const Part& b) {
  if (r.reused) return false;
  return r.status == Status::kInterference && !r.motion && !r.duplicate && !a.refinable() &&
         !b.refinable() && (convexity_unmeasured(a) || convexity_unmeasured(b));
}

// Measures the parts marked in `which`; a part that cannot be measured (its
// surface lost from the store) counts as nonconvex: the refinement decides
// its pairs and reports what it cannot read.
void measure(std::vector<Part>& parts, const std::vector<int>& which, const RunOptions& options) {
  parallel_for(which.size(), options.jobs, [&](size_t k) {
    Part& p = parts[size_t(which[k])];
    try {
      measure_convexity(p, options.cache_dir);
    } catch (const std::exception&) {
      p.convex = false;
    }
  });
}

}  // namespace

bool may_need_refinement(const PairResult& r, const Part& a, const Part& b) {
  return r.status == Status::kInterference && !r.motion && !r.duplicate &&
         (unmeasured_or_refinable(a) || unmeasured_or_refinable(b));
}

void measure_convexity_on_demand(std::vector<Part>& parts,
                                 const std::vector<std::pair<int, int>>& pairs,
                                 std::vector<PairResult>& results, const RunOptions& options,
                                 const std::function<PairChecks(int, int)>& checks) {
  // What the hull stage held back: its pairs are noted and reported below.
  std::vector<char> held(pairs.size(), 0);
  for (size_t k = 0; k < pairs.size(); ++k)
    held[k] = !results[k].reused &&
              may_need_refinement(results[k], parts[pairs[k].first], parts[pairs[k].second]);
  // Two rounds: the part with more open pairs first (ties: more vertices, then
  // the lower index), then the other part of each pair still open.
  for (int round = 0; round < 2; ++round) {
    std::vector<int> degree(parts.size(), 0);
    std::vector<size_t> still;
    for (size_t k = 0; k < pairs.size(); ++k) {
      const auto [a, b] = pairs[k];
      if (!open(results[k], parts[a], parts[b])) continue;
      still.push_back(k);
      ++degree[size_t(a)], ++degree[size_t(b)];
    }
    if (still.empty()) break;
    std::vector<char> chosen(parts.size(), 0);
    for (size_t k : still) {
      const auto [a, b] = pairs[k];
      const bool ua = convexity_unmeasured(parts[a]), ub = convexity_unmeasured(parts[b]);
      int pick = ua ? a : b;
      if (ua && ub && round == 0) {
        auto rank = [&](int p) { return std::make_pair(degree[size_t(p)], parts[p].vertex_count); };
        pick = rank(b) > rank(a) ? b : a;
      } else if (ua && ub) {
        chosen[size_t(b)] = 1;  // the second round settles every open pair
      }
      chosen[size_t(pick)] = 1;
    }
    std::vector<int> which;
    for (size_t p = 0; p < parts.size(); ++p)
      if (chosen[p]) which.push_back(static_cast<int>(p));
    measure(parts, which, options);
  }
  // Pairs stopped early for a part that turns out convex, with a convex
  // partner: their hulls decide, so they are solved on them in full.
  std::vector<size_t> again;
  for (size_t k = 0; k < pairs.size(); ++k) {
    const Part &a = parts[pairs[k].first], &b = parts[pairs[k].second];
    if (held[k] && results[k].stats.stop_reason == StopReason::kAboveTolerance && !a.refinable() &&
        !b.refinable()) {
      again.push_back(k);
      held[k] = 0;
    }
  }
  if (!again.empty()) solve_pairs(parts, pairs, again, options, checks, results);
  for (size_t k = 0; k < pairs.size(); ++k) {
    if (!held[k]) continue;
    PairResult& r = results[k];
    const Part &a = parts[pairs[k].first], &b = parts[pairs[k].second];
    note_hull_stage(r, a, b);
    if (options.on_pair && !needs_refinement(r, a, b)) options.on_pair(r, parts);
  }
}

}  // namespace pd
