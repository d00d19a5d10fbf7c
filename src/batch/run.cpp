#include "batch/run.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <stdexcept>

#include "batch/content_hashes.h"
#include "batch/progress.h"
#include "batch/refine.h"
#include "batch/run_stages.h"

namespace pd {

PairResult pair_result_from_worker(bool ok, const std::string& payload, int a, int b,
                                   const std::string& method) {
  std::string why = payload;
  if (ok) {
    try {
      return decode_pair_result(payload);
    } catch (const std::exception& e) {  // the pair is lost, never the batch
      why = std::string("worker result unreadable: ") + e.what();
    }
  }
  PairResult r;
  r.a = a;
  r.b = b;
  r.status = Status::kError;
  r.method = method;
  r.error = why;
  return r;
}

namespace {

using Clock = std::chrono::steady_clock;

/// Seconds since `t`, and `t` moved to now.
double lap(Clock::time_point& t) {
  const auto now = Clock::now();
  const double s = std::chrono::duration<double>(now - t).count();
  t = now;
  return s;
}

}  // namespace

RunResult run_scene(const SceneSpec& scene, const RunOptions& options) {
  const auto t0 = Clock::now();
  auto t = t0;
  RunResult out;
  const std::map<std::string, std::string> file_hashes = mesh_file_hashes(scene);
  const std::vector<std::string> hashes = part_content_hashes(scene, file_hashes);
  out.scene_hash = scene_content_hash(scene, hashes);
  out.settings_hash =
      settings_hash(options.solver, options.tolerance, scene.checks, scene.auto_tolerance);
  // A shard plans the whole scene without hulls, then loads only its parts.
  std::optional<ScenePlan> plan;
  std::vector<int> loaded;  // scene index of each loaded part (a shard's)
  SceneSpec shard_scene;
  if (options.shard) {
    plan = plan_scene(scene, options.shard->total, options.jobs, options.load_timeout,
                      options.faults.before_mesh_load);
    loaded = shard_parts(*plan, options.shard->index - 1);
    shard_scene.path = scene.path;
    shard_scene.units = scene.units;
    shard_scene.tolerance = scene.tolerance;
    shard_scene.auto_tolerance = scene.auto_tolerance;
    shard_scene.checks = scene.checks;
    for (int k : loaded) shard_scene.parts.push_back(scene.parts[k]);
    read_inline_vertices(shard_scene);  // only this shard's parts (scene/scene.h)
  } else if (std::any_of(scene.parts.begin(), scene.parts.end(),
                         [](const PartSpec& p) { return p.vertex_summary.has_value(); })) {
    shard_scene = scene;  // every part is loaded: every list read again
    read_inline_vertices(shard_scene);
  }
  const SceneSpec& to_load = plan || !shard_scene.parts.empty() ? shard_scene : scene;
  {
    Progress progress(to_load.parts.size(), options.quiet, "parts");
    out.parts = build_parts(
        to_load, options.jobs, [&](size_t n) { progress.tick(n); }, options.load_timeout,
        {options.cache_dir, &file_hashes}, options.load_memory_mb, options.faults.before_mesh_load);
    progress.finish();
  }
  for (size_t k = 0; k < out.parts.size(); ++k)
    out.part_hashes.push_back(hashes[plan ? loaded[k] : k]);
  out.stages.parts = lap(t);
  const std::vector<Part>& parts = out.parts;
  const Checks& checks = scene.checks;
  out.simulated = {"interference"};
  if (checks.clearance) out.simulated.push_back("clearance");
  if (checks.motion) out.simulated.push_back("motion");
  const auto pair_checks =
      pair_checks_of(parts, checks, scene.auto_tolerance, scene.units.value_or("mm"));

  CandidatePairs candidates;
  if (plan) {
    ShardManifest manifest;
    candidates = shard_pairs(*plan, *options.shard, loaded, parts, checks,
                             static_cast<long>(scene.parts.size()), manifest);
    out.shard = std::move(manifest);
  } else if (scene.pairs) {
    candidates = listed_pairs(parts, *scene.pairs);
  } else {
    candidates = broad_phase_pairs(parts, checks);
  }
  const std::vector<std::pair<int, int>>& pairs = candidates.pairs;
  out.all_pairs = candidates.all_pairs;
  out.culled = candidates.culled;
  out.unchecked = candidates.unchecked;
  out.stages.broad_phase = lap(t);

  out.pairs.resize(pairs.size());
  // --reuse: an unchanged pair keeps its old result (nonconvex parts' pairs are
  // solved again: their refinement runs after the hull stage).
  const std::vector<size_t> to_solve =
      reuse_results(parts, pairs, out.part_hashes, out.settings_hash, options, out.pairs);
  out.reused = static_cast<long>(pairs.size() - to_solve.size());
  solve_pairs(parts, pairs, to_solve, options, pair_checks, out.pairs);
  out.stages.solve = lap(t);
  refine_nonconvex_pairs(out.parts, pairs, out.pairs, options, pair_checks);
  out.stages.refine = lap(t);
  out.seconds = std::chrono::duration<double>(t - t0).count();
  return out;
}

}  // namespace pd
