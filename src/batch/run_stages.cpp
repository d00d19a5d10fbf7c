#include "batch/run_stages.h"

#include <algorithm>
#include <map>
#include <memory>
#include <optional>

#include "batch/broad_phase.h"
#include "batch/convexity_on_demand.h"
#include "batch/pair_workers.h"
#include "batch/progress.h"
#include "batch/refine.h"
#include "work_queue.h"

namespace pd {

CandidatePairs broad_phase_pairs(const std::vector<Part>& parts, const Checks& checks) {
  CandidatePairs out;
  const int n = static_cast<int>(parts.size());
  out.all_pairs = pair_count(n);
  std::vector<Aabb> boxes;
  std::vector<int> usable;
  for (int k = 0; k < n; ++k) {
    if (parts[k].error) continue;
    usable.push_back(k);
    boxes.push_back(culling_box(parts[k], checks));
  }
  for (const auto& [i, j] : overlapping_boxes(boxes, broad_phase_reach(checks)))
    out.pairs.emplace_back(usable[i], usable[j]);
  const long usable_pairs = pair_count(static_cast<long>(usable.size()));
  out.unchecked = out.all_pairs - usable_pairs;  // not the broad phase's doing
  out.culled = usable_pairs - static_cast<long>(out.pairs.size());
  return out;
}

CandidatePairs listed_pairs(const std::vector<Part>& parts,
                            const std::vector<std::pair<std::string, std::string>>& listed) {
  CandidatePairs out;
  std::map<std::string, int> index;
  for (int k = 0; k < static_cast<int>(parts.size()); ++k) index[parts[k].id] = k;
  for (const auto& [a, b] : listed) {
    const int ia = index.at(a), ib = index.at(b);
    out.pairs.emplace_back(std::min(ia, ib), std::max(ia, ib));
  }
  std::sort(out.pairs.begin(), out.pairs.end());
  out.pairs.erase(std::unique(out.pairs.begin(), out.pairs.end()), out.pairs.end());
  out.all_pairs = static_cast<long>(out.pairs.size());
  return out;
}

CandidatePairs shard_pairs(const ScenePlan& plan, const ShardSpec& shard,
                           const std::vector<int>& loaded, const std::vector<Part>& parts,
                           const Checks& checks, long scene_parts, ShardManifest& manifest) {
  CandidatePairs out;
  const int index = shard.index - 1;
  const int n = static_cast<int>(parts.size());
  std::vector<int> local(static_cast<size_t>(scene_parts), -1);
  for (size_t k = 0; k < loaded.size(); ++k) local[loaded[k]] = static_cast<int>(k);
  std::vector<Aabb> boxes(n);
  for (int k = 0; k < n; ++k)
    if (!parts[k].error) boxes[k] = culling_box(parts[k], checks);
  const double reach = broad_phase_reach(checks);
  ShardManifest m;
  m.shard = shard;
  m.parts_total = scene_parts;
  m.part_index = loaded;
  for (int k : loaded)
    if (plan.owner[k] == index) m.owned.push_back(k);
  for (const Part& p : parts) m.vertices_loaded += p.vertex_count;
  m.vertices_total = plan.vertices_total;
  for (size_t p = 0; p < plan.pairs.size(); ++p) {
    if (plan.pair_shard[p] != index) continue;
    ++m.pairs_planned;
    const int a = local[plan.pairs[p].first], b = local[plan.pairs[p].second];
    if (plan.listed) {
      out.pairs.emplace_back(a, b);
    } else if (parts[a].error || parts[b].error) {
      ++out.unchecked;
    } else if (boxes_touch(boxes[a], boxes[b], reach)) {
      out.pairs.emplace_back(a, b);
    } else {
      ++out.culled;
    }
  }
  m.pairs_total = plan.listed ? static_cast<long>(plan.pairs.size()) : pair_count(m.parts_total);
  out.all_pairs = m.pairs_planned;
  m.pairs_checked = static_cast<long>(out.pairs.size());
  m.listed = plan.listed;
  manifest = std::move(m);
  return out;
}

std::function<PairChecks(int, int)> pair_checks_of(
    const std::vector<Part>& parts, const Checks& checks,
    const std::optional<AutoTolerance>& auto_tolerance, const std::string& units) {
  // Clearance per pair: the scene's minimum, or a named pair's own.
  std::map<std::pair<std::string, std::string>, double> own_clearance;
  if (checks.clearance)
    for (const auto& e : checks.clearance->pairs)
      own_clearance[{std::min(e.a, e.b), std::max(e.a, e.b)}] = e.min;
  return [&parts, &checks, own_clearance, auto_tolerance, units](int a, int b) {
    PairChecks pc;
    pc.units = units;
    if (auto_tolerance && parts[a].sag && parts[b].sag)
      pc.tolerance = pair_tolerance(parts[a], parts[b], *auto_tolerance, units);
    if (checks.clearance) {
      const auto it = own_clearance.find(
          {std::min(parts[a].id, parts[b].id), std::max(parts[a].id, parts[b].id)});
      pc.clearance = it == own_clearance.end() ? checks.clearance->min : it->second;
    }
    if (checks.motion && (parts[a].motion || parts[b].motion)) pc.motion = &*checks.motion;
    return pc;
  };
}

namespace {

// Whether an old result was decided against the tolerance and clearance the
// pair has now (both follow from the parts and the settings, but rules can set
// a pair's own). Under tolerance auto a refined pair was decided again against
// the band at its contact (batch/contact_band.h), which a decided result gives
// back unchanged: it is noted again, and must come out as it was.
bool same_pair_checks(const PairResult& prior, const PairChecks& pc) {
  if (prior.clearance_min != pc.clearance) return false;
  if (!pc.tolerance) return !prior.tolerance;
  PairResult again = prior;
  note_pair_tolerance(again, pc);
  return again.tolerance == prior.tolerance && again.status == prior.status &&
         again.tolerance_basis == prior.tolerance_basis;
}

}  // namespace

std::vector<size_t> reuse_results(const std::vector<Part>& parts,
                                  const std::vector<std::pair<int, int>>& pairs,
                                  const std::vector<std::string>& part_hashes,
                                  const std::string& settings_hash, const RunOptions& options,
                                  std::vector<PairResult>& results,
                                  const std::function<PairChecks(int, int)>& checks,
                                  ReuseCounts* counts) {
  std::vector<size_t> to_solve;
  for (size_t k = 0; k < pairs.size(); ++k) {
    const auto [a, b] = pairs[k];
    std::optional<PairResult> prior;
    ReuseMiss why = ReuseMiss::kSettings;
    if (options.reuse)
      prior = prior_result(*options.reuse, settings_hash, a, parts[a].id, part_hashes[a], b,
                           parts[b].id, part_hashes[b], &why);
    if (prior && checks && !same_pair_checks(*prior, checks(a, b))) {
      prior.reset();  // decided against another tolerance or clearance: solve again
      why = ReuseMiss::kPairChecks;
    }
    if (!prior) {
      to_solve.push_back(k);
      if (counts && options.reuse) ++counts->solved[reuse_miss_key(why)];
      continue;
    }
    if (counts) ++counts->reused;
    results[k] = *prior;
    if (options.on_pair) options.on_pair(results[k], parts);
  }
  return to_solve;
}

void solve_pairs(const std::vector<Part>& parts, const std::vector<std::pair<int, int>>& pairs,
                 std::vector<size_t> to_solve, const RunOptions& options,
                 const std::function<PairChecks(int, int)>& checks,
                 std::vector<PairResult>& results) {
  auto job = [&](size_t k) {
    const auto [a, b] = pairs[k];
    return PairJob{a, b, &parts[a], &parts[b]};
  };
  auto done = [&](size_t k, PairResult r) {
    note_hull_stage(r, parts[r.a], parts[r.b]);
    note_pair_tolerance(r, checks(r.a, r.b));
    results[k] = r;
    // Held back while a part's convexity or the refinement may change it.
    if (options.on_pair && !needs_refinement(r, parts[r.a], parts[r.b]) &&
        !turns_on_convexity(r, parts[r.a], parts[r.b]))
      options.on_pair(r, parts);
  };
  std::function<void(size_t)> before_task;
  if (options.faults.before_pair_solve)
    before_task = [&](size_t k) {
      options.faults.before_pair_solve(parts[pairs[k].first], parts[pairs[k].second]);
    };
  solve_pairs_in_workers(std::move(to_solve), job, options, checks, "pairs", done, before_task);
}

}  // namespace pd
