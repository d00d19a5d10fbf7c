#include "batch/run.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <stdexcept>

#include "batch/brep_confirm.h"
#include "batch/content_hashes.h"
#include "batch/progress.h"
#include "batch/refine.h"
#include "batch/rule_scope.h"
#include "batch/run_stages.h"
#include "brep/brep_file.h"
#include "scene/setup_warnings.h"
#include "scene/units.h"

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

// A part whose size is off its neighbours' by a units factor. Every part of
// the scene is compared, also in a shard (from the plan's boxes, which are the
// parts' placed boxes), so a shard warns as the unsharded run does.
void warn_units_like_sizes(const SceneSpec& scene, std::vector<Part>& parts, const ScenePlan* plan,
                           const std::vector<int>& loaded, const std::string& units) {
  const std::vector<PartSpec>& specs = scene.parts;  // a part per spec, in order
  std::vector<UnitsLikePart> seen(plan ? plan->boxes.size() : parts.size());
  for (size_t k = 0; k < seen.size(); ++k) {
    if (plan) {
      seen[k].box = plan->boxes[k];
    } else if (!parts[k].error) {
      seen[k].box = parts[k].box;
    }
    if (k >= specs.size()) continue;
    const PartSpec& s = specs[k];
    seen[k].unit_mm = s.to_scene_units * unit_in_mm(units).value_or(1.0);
    if (s.mesh && is_brep_path(*s.mesh))
      seen[k].unit_from_file = true;  // a STEP file states its unit, the reader converts it
    else if (s.mesh && format_unit(*s.mesh) && !s.units_key)
      seen[k].format_unit = format_unit(*s.mesh);  // glTF: metres, by its specification
  }
  const auto off = units_like_outliers(seen);
  for (size_t k = 0; k < parts.size(); ++k) {
    const size_t at = plan ? size_t(loaded[k]) : k;
    if (off[at] && !parts[k].error)
      parts[k].warnings.push_back(units_like_warning(seen[at], *off[at], units));
  }
}

// A false positive whose tolerance is at least the smaller part's size: any
// overlap of that pair would have passed.
void warn_tolerance_covers_part(const std::vector<Part>& parts, double tolerance,
                                const std::string& units, std::vector<PairResult>& results) {
  for (PairResult& r : results) {
    if (r.status != Status::kFalsePositive || r.a < 0 || r.b < 0) continue;
    const auto w = tolerance_covers_part(tolerance, parts[r.a], parts[r.b], units);
    if (w && std::find(r.warnings.begin(), r.warnings.end(), *w) == r.warnings.end())
      r.warnings.push_back(*w);
  }
}

// Each part's tags and group, and under rules the sets it belongs to.
std::vector<PartLabels> part_labels(const SceneSpec& scene, const std::vector<int>& loaded,
                                    size_t count, const RuleScope* rules) {
  std::vector<PartLabels> out(count);
  bool any = rules != nullptr;
  for (size_t k = 0; k < count; ++k) {
    const int at = loaded.empty() ? int(k) : loaded[k];
    const PartSpec& p = scene.parts[at];
    out[k].tags = p.tags;
    out[k].group = p.group;
    if (rules) out[k].sets = rules->index().sets_of(at);
    any = any || !p.tags.empty() || !p.group.empty();
  }
  if (!any) out.clear();
  return out;
}

// The rules on the candidates: out-of-scope and ignored pairs dropped, each
// kept pair's tolerance and clearance its rules', a streamed pair named as the
// report names it.
void scope_candidates(RuleScope& rules, CandidatePairs& candidates,
                      std::function<PairChecks(int, int)>& pair_checks, const RunOptions& options,
                      RunOptions& run_options) {
  rules.apply(candidates);
  pair_checks = rules.pair_checks(std::move(pair_checks));
  if (options.on_pair)
    run_options.on_pair = [&rules, &options](const PairResult& r, const std::vector<Part>& p) {
      PairResult named = r;
      rules.note(named);
      options.on_pair(named, p);
    };
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
  // Rules resolved once, against every part of the scene (a shard's too), before
  // any mesh is read: a set that selects nothing is bad input (exit 2).
  std::optional<RuleScope> rules;
  if (scene.rules) rules.emplace(scene, loaded);
  const SceneSpec& to_load = plan || !shard_scene.parts.empty() ? shard_scene : scene;
  {
    Progress progress(to_load.parts.size(), options.quiet, "parts");
    out.parts = build_parts(
        to_load, options.jobs, [&](size_t n) { progress.tick(n); }, options.load_timeout,
        {options.cache_dir, &file_hashes}, options.load_memory_mb, options.faults.before_mesh_load);
    progress.finish();
  }
  scene.brep_reads.reset();  // the parts have their meshes: the files' go
  shard_scene.brep_reads.reset();
  for (size_t k = 0; k < out.parts.size(); ++k)
    out.part_hashes.push_back(hashes[plan ? loaded[k] : k]);
  out.labels = part_labels(scene, loaded, out.parts.size(), rules ? &*rules : nullptr);
  const std::string units = scene.units.value_or("mm");
  warn_units_like_sizes(scene, out.parts, plan ? &*plan : nullptr, loaded, units);
  out.stages.parts = lap(t);
  const std::vector<Part>& parts = out.parts;
  const Checks& checks = scene.checks;
  out.simulated = {"interference"};
  if (checks.clearance) out.simulated.push_back("clearance");
  if (checks.motion) out.simulated.push_back("motion");
  auto pair_checks =
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
  RunOptions run_options = options;
  if (rules) scope_candidates(*rules, candidates, pair_checks, options, run_options);
  // A pair with a B-rep part is reported once its exact check is made.
  const auto on_pair = run_options.on_pair;
  if (on_pair)
    run_options.on_pair = [&, on_pair](const PairResult& r, const std::vector<Part>& p) {
      if (!held_for_exact(p[r.a], p[r.b])) on_pair(r, p);
    };
  const std::vector<std::pair<int, int>>& pairs = candidates.pairs;
  out.all_pairs = candidates.all_pairs;
  out.culled = candidates.culled;
  out.unchecked = candidates.unchecked;
  out.stages.broad_phase = lap(t);

  out.pairs.resize(pairs.size());
  // --reuse: an unchanged pair keeps its old result (a nonconvex pair its
  // refined one, which the refinement then leaves as it is).
  if (run_options.reuse) out.reuse.emplace();
  const std::vector<size_t> to_solve =
      reuse_results(parts, pairs, out.part_hashes, out.settings_hash, run_options, out.pairs,
                    pair_checks, out.reuse ? &*out.reuse : nullptr);
  solve_pairs(parts, pairs, to_solve, run_options, pair_checks, out.pairs);
  out.stages.solve = lap(t);
  refine_nonconvex_pairs(out.parts, pairs, out.pairs, run_options, pair_checks);
  out.stages.refine = lap(t);
  run_options.on_pair = on_pair;
  confirm_brep_pairs(out.parts, pairs, out.pairs, run_options, pair_checks, units);
  out.stages.exact = lap(t);
  if (rules) {
    for (PairResult& r : out.pairs) rules->note(r);
    out.rules = rules->coverage();
  }
  warn_tolerance_covers_part(out.parts, options.tolerance, units, out.pairs);
  out.stages.refine += lap(t);
  out.seconds = std::chrono::duration<double>(t - t0).count();
  return out;
}

}  // namespace pd
