#include "report/run_config.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <istream>
#include <iterator>

#include "batch/progress.h"
#include "batch/rule_scope.h"
#include "cache_file.h"
#include "memory_limit.h"
#include "report/prior_report.h"
#include "report/prior_settings.h"
#include "report/report_json.h"
#include "results/fingerprint.h"
#include "scene/rule_index.h"
#include "scene/split_nodes.h"
#include "scene/units.h"

namespace pd {

namespace {

std::optional<ShardSpec> resolve_shard(const CheckArgs& a,
                                       const std::function<const char*(const char*)>& getenv) {
  std::optional<ShardSpec> shard;
  if (a.shard && *a.shard == "auto") {
    shard = shard_from_environment(getenv, a.shard_total, a.shard_base);
  } else {
    if (a.shard_total || a.shard_base)
      throw ShardError("--shard-total and --shard-base go with --shard auto");
    if (a.shard) shard = parse_shard(*a.shard);
  }
  if (!shard) return shard;
  if (a.format != "json")
    throw ShardError("--shard writes a JSON report (--format json) for pdcheck merge");
  const std::pair<const char*, bool> whole_run[] = {
      {"--baseline", !a.review.baseline.empty()},
      {"--suppressions", !a.review.suppressions.empty()},
      {"--write-suppressions", a.extra.write_suppressions.has_value()},
      {"--junit", a.extra.junit.has_value()},
      {"--sarif", a.extra.sarif.has_value()},
      {"--html", a.extra.html.has_value()},
      {"--csv", a.extra.csv.has_value()},
      {"--bcf", a.extra.bcf.has_value()}};
  for (const auto& [option, given] : whole_run)
    if (given)
      throw ShardError(std::string("--shard: ") + option +
                       " applies to the whole run, not to one shard");
  return shard;
}

// The scene with the command line's overrides over it.
// The run's --memory budget (MB): given, else memory_budget_mb's share.
double run_memory_mb(const CheckArgs& a) {
  return a.memory.empty() ? memory_budget_mb(available_memory_mb()) : parse_memory_mb(a.memory);
}

SceneSpec load_scene(const CheckArgs& a, bool shard, std::istream& in, SolverSettings& solver) {
  std::optional<std::string> units;
  if (!a.units.empty()) {
    if (!unit_in_mm(a.units))
      throw SceneError("--units: unknown unit \"" + a.units + "\" (use " + kUnitNames + ")");
    units = a.units;
  }
  SceneSpec scene;
  if (a.scene == "-") {
    std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    scene = parse_stdin_scene(text, units, a.jobs);
  } else {
    scene = load_scene_file(a.scene, units, a.jobs, /*keep_vertices=*/!shard);
  }
  // Node parts are parts from here on: rules, pairs and shards plan with them.
  std::optional<Progress> split_progress;
  split_node_parts(scene,
                   {a.jobs,
                    a.load_timeout,
                    a.load_memory,
                    {},
                    a.no_cache            ? ""
                    : a.cache_dir.empty() ? default_cache_dir()
                                          : a.cache_dir,
                    run_memory_mb(a),
                    [&](size_t files) { split_progress.emplace(files, a.quiet, "files split"); },
                    [&] { split_progress->tick(); }});
  if (split_progress) split_progress->finish();
  if (a.tolerance && *a.tolerance == "auto") {
    if (!scene.auto_tolerance) {  // a scene's own auto keeps its clamps
      scene.auto_tolerance = AutoTolerance{};
      scene.tolerance = 0.0;
    }
  } else if (a.tolerance) {
    // A unit suffix is converted to the scene's unit, which is known by now.
    const auto length = parse_length(*a.tolerance);
    if (!length)
      throw SceneError("--tolerance: expected a length such as 0.05 or 0.05mm (units " +
                       std::string(kUnitNames) + "), or auto, got \"" + *a.tolerance + "\"");
    const double tolerance = length_in(*length, scene.units.value_or("mm"));
    if (!(tolerance > 0 && std::isfinite(tolerance)))
      throw SceneError("--tolerance: must be a finite length > 0");
    scene.tolerance = tolerance;
    scene.auto_tolerance.reset();
  }
  if (!a.rules.empty()) {
    if (scene.rules)
      throw SceneError("--rules " + a.rules + ": the scene " + scene.path +
                       " has its own \"rules\": give the rules in one place");
    attach_rules(scene, load_rules_file(a.rules, scene.units.value_or("mm")));
  }
  if (scene.rules) RuleIndex check(*scene.rules, scene.parts);  // an empty set: exit 2 now
  if (!scene.tolerance)
    throw SceneError(scene.path + ": no tolerance: give \"tolerance\" in the scene or --tolerance");
  if (const auto empty = empty_scene_problem(scene); empty && !a.allow_empty)
    throw SceneError(*empty);
  scene.solver.apply(solver);
  if (!a.method.empty()) {
    const auto m = parse_method(a.method);
    if (!m)
      throw SceneError("--method: unknown method \"" + a.method +
                       "\" (mlsl, mlsl-paper, gs-local, grid, exact)");
    solver.method = *m;
  }
  if (a.seed) solver.seed = *a.seed;
  if (!a.pieces.empty()) {
    const auto p = parse_pieces(a.pieces);
    if (!p)
      throw SceneError("--pieces: unknown value \"" + a.pieces + "\" (use " + kPiecesNames + ")");
    override_pieces(scene, *p);
  }
  return scene;
}

}  // namespace

void resolve_run_config(const CheckArgs& a, std::istream& in,
                        const std::function<const char*(const char*)>& getenv, RunConfig& out) {
  out.shard = resolve_shard(a, getenv);
  // Every output path is checked before the run.
  if (a.output) out.out_file = check_output_file("-o", *a.output);
  out.extra = check_extra_outputs(a.extra);
  const auto load_start = std::chrono::steady_clock::now();
  SolverSettings solver;
  out.scene = load_scene(a, out.shard.has_value(), in, solver);
  // The CI inputs are read before the run: a malformed file costs no solve. A
  // prior report in another unit is refused; other settings that differ are said.
  const ReportContext run_settings{out.scene.path,
                                   out.scene.units.value_or("mm"),
                                   *out.scene.tolerance,
                                   solver,
                                   0.0,
                                   out.scene.auto_tolerance,
                                   out.scene.rules ? rules_hash(out.scene) : ""};
  if (!a.reuse.empty()) {
    PriorSettings s;
    out.prior = load_prior_report(a.reuse, &s);
    out.prior_warnings = check_prior_settings("--reuse", a.reuse, s, run_settings);
  }
  load_review_inputs(a.review, *out.scene.tolerance, out.review);
  if (out.review.baseline)
    for (const auto& w : check_prior_settings("--baseline", out.review.baseline->path,
                                              out.review.baseline->settings, run_settings))
      out.prior_warnings.push_back(w);
  out.review.options.units = run_settings.units;
  if (out.scene.rules) {
    out.review.expected = expected_rules_of(*out.scene.rules);
    out.review.options.expected = &*out.review.expected;
  }
  // A shard's parts are some of the scene's: its merge judges an empty run.
  out.review.options.allow_empty = a.allow_empty || out.shard.has_value();
  out.review.options.deferred = out.shard.has_value();
  if (out.scene.pairs) {
    out.review.options.listed.emplace();
    for (const auto& [x, y] : *out.scene.pairs)
      out.review.options.listed->insert(pair_fingerprint(x, y));
  }
  out.load_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start).count();
  RunOptions& o = out.options;
  o.solver = solver;
  o.tolerance = *out.scene.tolerance;
  o.jobs = a.jobs;
  o.pair_timeout = a.pair_timeout;
  o.load_timeout = a.load_timeout;
  o.load_memory_mb = a.load_memory;
  o.memory_mb = run_memory_mb(a);
  o.quiet = a.quiet;
  o.shard = out.shard;
  if (!a.no_cache) o.cache_dir = a.cache_dir.empty() ? default_cache_dir() : a.cache_dir;
}

}  // namespace pd
