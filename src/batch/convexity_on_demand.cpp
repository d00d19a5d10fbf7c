#include "batch/convexity_on_demand.h"

#include <algorithm>
#include <memory>
#include <tuple>

#include "batch/refine.h"
#include "batch/run_stages.h"
#include "scene/part_convexity.h"

namespace pd {

namespace {

// The hull stage found the hulls interfering (a refined pair taken from an
// earlier report carries its hull depth; a duplicate overlaps wholly).
bool hulls_interfered(const PairResult& r) {
  if (r.duplicate) return false;
  if (r.reused)
    return r.hull_depth.has_value() ||
           (r.status == Status::kInterference && r.depth_source == "hull");
  return r.status == Status::kInterference;
}

// How likely a part is nonconvex, from what loading it told: vertices read
// per hull vertex. A convex mesh has every vertex on its hull (an STL file
// repeats each about 6 times: a ball reads ~7.5 per hull vertex), a bore, a
// groove or a pocket keeps many off it (a bearing ring ~300, a nut ~20).
double off_hull(const Part& p) {
  return double(p.vertex_count) / double(std::max(1L, p.hull_vertex_count()));
}

// The pair's on-demand parts in the order it measures them: the likelier
// nonconvex first (its answer may settle the pair), then the one with more
// vertices, then by id: the same in every shard.
std::vector<int> measuring_order(const std::vector<Part>& parts, int a, int b) {
  std::vector<int> order;
  for (int p : {a, b})
    if (parts[size_t(p)].convexity_on_demand() && !parts[size_t(p)].error) order.push_back(p);
  if (order.size() == 2) {
    const Part &x = parts[size_t(order[0])], &y = parts[size_t(order[1])];
    if (std::make_tuple(off_hull(y), y.vertex_count, x.id) >
        std::make_tuple(off_hull(x), x.vertex_count, y.id))
      std::swap(order[0], order[1]);
  }
  return order;
}

}  // namespace

bool turns_on_convexity(const PairResult& r, const Part& a, const Part& b) {
  return (a.convexity_on_demand() || b.convexity_on_demand()) && hulls_interfered(r);
}

ConvexityOnDemand::ConvexityOnDemand(std::vector<Part>& parts,
                                     const std::vector<std::pair<int, int>>& pairs,
                                     const std::vector<PairResult>& results,
                                     const std::function<PairChecks(int, int)>& checks,
                                     const std::string& cache_dir, PartSolids& solids)
    : parts_(parts),
      pairs_(pairs),
      checks_(checks),
      cache_dir_(cache_dir),
      solids_(solids),
      open_(pairs.size(), 0),
      measured_(parts.size(), 0) {
  for (size_t k = 0; k < pairs.size(); ++k)
    open_[k] = turns_on_convexity(results[k], parts[size_t(pairs[k].first)],
                                  parts[size_t(pairs[k].second)]);
}

bool ConvexityOnDemand::measured_convex(int p) {
  const Part& part = parts_[size_t(p)];
  const std::string key = convexity_key_of(part);
  std::shared_ptr<std::promise<std::optional<StoredConvexity>>> mine;
  std::shared_future<std::optional<StoredConvexity>> value;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    measured_[size_t(p)] = 1;
    auto it = by_file_.find(key);
    if (it == by_file_.end()) {
      mine = std::make_shared<std::promise<std::optional<StoredConvexity>>>();
      value = mine->get_future().share();
      by_file_.emplace(key, value);
    } else {
      value = it->second;
    }
  }
  if (mine) {
    // A part placed as its file is measured with the distances its pairs
    // are refined with (built here when not kept); another instance measures
    // on its own, since its distances are of its placed surface.
    const auto prepared = [&](const Mesh& file_mesh) -> std::shared_ptr<const PreparedMesh> {
      if (!placed_as_file(part)) return nullptr;
      const std::shared_ptr<const SolidDistance> d = solids_.of(p, file_mesh);
      return {d, &d->mesh()};  // keeps the distances alive
    };
    std::optional<StoredConvexity> c;
    try {
      c = measure_file_convexity(part, cache_dir_, prepared);
    } catch (const std::exception&) {  // counts as nonconvex (finish)
    }
    mine->set_value(c);
  }
  const std::optional<StoredConvexity>& c = value.get();
  return c && convex_by(part, *c);
}

PairConvexity ConvexityOnDemand::settle(size_t k) {
  const int a = pairs_[k].first, b = pairs_[k].second;
  const Part &pa = parts_[size_t(a)], &pb = parts_[size_t(b)];
  PairConvexity known{pa.convex, pb.convex};
  if (!open_[k]) return known;
  const auto measure = [&](int p) {
    const bool convex = measured_convex(p);
    (p == a ? known.a : known.b) = convex;
    return convex;
  };
  const std::vector<int> order = measuring_order(parts_, a, b);
  const PairChecks c = checks_(a, b);
  if (c.clearance || pa.mode == Pieces::kDecompose || pb.mode == Pieces::kDecompose) {
    for (int p : order)  // each nonconvex part is decomposed
      if (convexity_unmeasured(parts_[size_t(p)])) measure(p);
    return known;
  }
  if (pa.refinable() || pb.refinable()) return known;  // decided on the surfaces
  for (int p : order)
    if (convexity_unmeasured(parts_[size_t(p)]) && !measure(p)) break;
  return known;
}

void ConvexityOnDemand::finish(std::vector<PairResult>& results, const RunOptions& options) {
  for (size_t p = 0; p < parts_.size(); ++p) {
    if (!measured_[p]) continue;
    const std::optional<StoredConvexity>& c = by_file_.at(convexity_key_of(parts_[p])).get();
    if (c)
      set_convexity(parts_[p], *c);
    else
      parts_[p].convex = false;
  }
  // Pairs stopped early for a part that turned out convex, with a convex
  // partner: their hulls decide, so they are solved on them in full.
  std::vector<size_t> again;
  for (size_t k = 0; k < pairs_.size(); ++k) {
    if (!open_[k]) continue;
    const Part &a = parts_[size_t(pairs_[k].first)], &b = parts_[size_t(pairs_[k].second)];
    if (!results[k].reused && results[k].stats.stop_reason == StopReason::kAboveTolerance &&
        !a.refinable() && !b.refinable())
      again.push_back(k);
  }
  if (!again.empty()) solve_pairs(parts_, pairs_, again, options, checks_, results);
  for (size_t k = 0; k < pairs_.size(); ++k) {
    PairResult& r = results[k];
    if (!open_[k] || r.reused) continue;
    const Part &a = parts_[size_t(pairs_[k].first)], &b = parts_[size_t(pairs_[k].second)];
    note_hull_stage(r, a, b);
    if (options.on_pair && !needs_refinement(r, a, b)) options.on_pair(r, parts_);
  }
}

}  // namespace pd
