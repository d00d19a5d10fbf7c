#include "batch/convexity_on_demand.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <tuple>

#include "batch/locality.h"
#include "batch/progress.h"
#include "batch/refine.h"
#include "batch/run_stages.h"
#include "parallel_for.h"
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

// The parts the pair still needs measured, given what is known so far.
std::vector<int> still_needed(const std::vector<Part>& parts, int a, int b,
                              const PairChecks& checks) {
  const Part &pa = parts[size_t(a)], &pb = parts[size_t(b)];
  std::vector<int> need;
  const std::vector<int> order = measuring_order(parts, a, b);
  const bool pieces =
      checks.clearance || pa.mode == Pieces::kDecompose || pb.mode == Pieces::kDecompose;
  if (pieces) {  // each nonconvex part is decomposed
    for (int p : order)
      if (convexity_unmeasured(parts[size_t(p)])) need.push_back(p);
    return need;
  }
  if (pa.refinable() || pb.refinable()) return need;  // decided on the surfaces
  for (int p : order)
    if (convexity_unmeasured(parts[size_t(p)])) return {p};
  return need;
}

// Measures the parts marked in `which`, each file at each stretch once (its
// instances share the answer); a part that cannot be measured (its surface
// lost from the store) counts as nonconvex: the refinement decides its pairs
// and reports what it cannot read.
// A file placed as it is by one of its instances is measured with that
// instance's distances from `solids`, which the refinement then finds built.
void measure(std::vector<Part>& parts, const std::vector<int>& which, const RunOptions& options,
             PartSolids& solids) {
  std::map<std::string, std::vector<int>> by_key;  // ordered: the same order on every run
  for (int p : which) by_key[convexity_key_of(parts[size_t(p)])].push_back(p);
  std::vector<const std::vector<int>*> files;
  for (const auto& [key, instances] : by_key) files.push_back(&instances);
  // Against the refinement's order (batch/locality.h): the files it asks for
  // first are measured last, so the distances the cache keeps when the
  // measures end are the ones it needs first (a budget smaller than every
  // measured part's distances drops the others). Each file's measure is its
  // own: the order changes no result.
  const std::vector<std::uint64_t> code = locality_codes(parts);
  const auto where = [&](const std::vector<int>* instances) {  // of the instance the cache keeps
    for (int p : *instances)
      if (placed_as_file(parts[size_t(p)])) return code[size_t(p)];
    return code[size_t(instances->front())];
  };
  std::stable_sort(files.begin(), files.end(),
                   [&](const auto* x, const auto* y) { return where(x) > where(y); });
  // When the budget holds every measured part's distances, none is dropped
  // whatever the order: then the largest first, so that the threads end
  // together (a bearing's two rings measured last kept one thread waiting
  // for the other's 0.3 s while the small parts were done). The size is the
  // vertices read, which only estimates the faces' count (three a face in an
  // STL file, about half a face in an indexed one): a low estimate costs only
  // the order's benefit (distances dropped and built again), never a result.
  const auto size_of = [&](const std::vector<int>* instances) {
    return parts[size_t(instances->front())].vertex_count;
  };
  size_t all = 0;
  for (const auto* f : files) all += solid_bytes(size_of(f));
  if (all <= size_t(std::max(0.0, options.memory_mb)) << 20)
    std::stable_sort(files.begin(), files.end(),
                     [&](const auto* x, const auto* y) { return size_of(x) > size_of(y); });
  Progress progress(files.size(), options.quiet, "convexity measures");
  parallel_for(files.size(), options.jobs, [&](size_t k) {
    const std::vector<int>& instances = *files[k];
    std::optional<StoredConvexity> c;
    const auto as_file = std::find_if(instances.begin(), instances.end(),
                                      [&](int p) { return placed_as_file(parts[size_t(p)]); });
    const auto prepared = [&](const Mesh& file_mesh) -> std::shared_ptr<const PreparedMesh> {
      if (as_file == instances.end()) return nullptr;
      const std::shared_ptr<const SolidDistance> d = solids.of(*as_file, file_mesh);
      return {d, &d->mesh()};  // keeps the distances alive
    };
    try {
      c = measure_file_convexity(parts[size_t(instances.front())], options.cache_dir, prepared);
    } catch (const std::exception&) {
    }
    for (int p : instances) {
      if (c)
        set_convexity(parts[size_t(p)], *c);
      else
        parts[size_t(p)].convex = false;
    }
    // The distances the cache let go go back to the system, not to a
    // thread's heap that would keep them resident through the refinement
    // (100M triangles: 0.9 GB of them). The file's mesh stays in the heap
    // for the next measure.
    solids.give_back_dropped();
    progress.tick();
  });
  progress.finish();
}

}  // namespace

bool turns_on_convexity(const PairResult& r, const Part& a, const Part& b) {
  return (a.convexity_on_demand() || b.convexity_on_demand()) && hulls_interfered(r);
}

void measure_convexity_on_demand(std::vector<Part>& parts,
                                 const std::vector<std::pair<int, int>>& pairs,
                                 std::vector<PairResult>& results, const RunOptions& options,
                                 const std::function<PairChecks(int, int)>& checks,
                                 PartSolids& solids) {
  std::vector<size_t> open;
  for (size_t k = 0; k < pairs.size(); ++k)
    if (turns_on_convexity(results[k], parts[size_t(pairs[k].first)],
                           parts[size_t(pairs[k].second)]))
      open.push_back(k);
  // At most two rounds: a pair's first part, then its second where the first
  // was convex.
  for (;;) {
    std::vector<char> chosen(parts.size(), 0);
    for (size_t k : open)
      for (int p : still_needed(parts, pairs[k].first, pairs[k].second,
                                checks(pairs[k].first, pairs[k].second)))
        chosen[size_t(p)] = 1;
    std::vector<int> which;
    for (size_t p = 0; p < parts.size(); ++p)
      if (chosen[p]) which.push_back(static_cast<int>(p));
    if (which.empty()) break;
    measure(parts, which, options, solids);
  }
  // Pairs stopped early for a part that turned out convex, with a convex
  // partner: their hulls decide, so they are solved on them in full.
  std::vector<size_t> again;
  for (size_t k : open) {
    const Part &a = parts[size_t(pairs[k].first)], &b = parts[size_t(pairs[k].second)];
    if (!results[k].reused && results[k].stats.stop_reason == StopReason::kAboveTolerance &&
        !a.refinable() && !b.refinable())
      again.push_back(k);
  }
  if (!again.empty()) solve_pairs(parts, pairs, again, options, checks, results);
  for (size_t k : open) {
    PairResult& r = results[k];
    if (r.reused) continue;
    const Part &a = parts[size_t(pairs[k].first)], &b = parts[size_t(pairs[k].second)];
    note_hull_stage(r, a, b);
    if (options.on_pair && !needs_refinement(r, a, b)) options.on_pair(r, parts);
  }
}

}  // namespace pd
