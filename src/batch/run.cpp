#include "batch/run.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "batch/content_hashes.h"
#include "batch/progress.h"
#include "batch/refine.h"
#include "batch/run_stages.h"

namespace pd {

using nlohmann::json;

std::string encode_pair_result(const PairResult& r) {
  json j = {{"a", r.a},
            {"b", r.b},
            {"s", int(r.status)},
            {"d", r.depth},
            {"v", {r.direction.x(), r.direction.y(), r.direction.z()}},
            {"g", r.margin},
            {"m", r.method},
            {"t", r.time_ms},
            {"f", r.fallback},
            {"e", r.error},
            {"st",
             {r.stats.alpha_evaluations, r.stats.local_solves, r.stats.distinct_optima,
              r.stats.ipopt_iterations, r.stats.ipopt_calls, r.stats.ipopt_failures,
              r.stats.mlsl_iterations, int(r.stats.stop_reason)}}};
  if (r.distance) j["x"] = *r.distance;
  if (r.clearance_min) j["c"] = *r.clearance_min;
  if (!r.warnings.empty()) j["w"] = r.warnings;
  if (r.pieces) j["pc"] = *r.pieces;
  if (r.motion) {
    const MotionTrace& m = *r.motion;
    j["mo"] = {{"n", m.steps},
               {"d", m.max_depth},
               {"td", m.t_max_depth},
               {"tc", m.t_min_distance},
               {"s", m.series}};
    if (m.min_distance) j["mo"]["c"] = *m.min_distance;
  }
  // MessagePack, not JSON text: it keeps every double's bits (NaN, ±Inf, −0
  // included), where dump() would write NaN and Inf as null.
  const std::vector<std::uint8_t> bytes = json::to_msgpack(j);
  return std::string(bytes.begin(), bytes.end());
}

PairResult decode_pair_result(const std::string& s) {
  // Not const: a missing key reads as null and throws on conversion (const
  // operator[] would be undefined behaviour).
  json j = json::from_msgpack(s);
  PairResult r;
  r.a = j["a"];
  r.b = j["b"];
  const int status = j["s"];
  if (status < int(Status::kSeparated) || status > int(Status::kUndecided))
    throw std::runtime_error("unknown status " + std::to_string(status));
  r.status = static_cast<Status>(status);
  r.depth = j["d"];
  r.direction = Vec3(j["v"][0], j["v"][1], j["v"][2]);
  r.margin = j["g"];
  r.method = j["m"];
  r.time_ms = j["t"];
  r.fallback = j["f"];
  r.error = j["e"];
  const auto& st = j["st"];
  r.stats = {st[0], st[1], st[2], st[3], st[4], st[5], st[6], StopReason(st[7].get<int>())};
  if (j.contains("x")) r.distance = j["x"].get<double>();
  if (j.contains("c")) r.clearance_min = j["c"].get<double>();
  if (j.contains("w")) r.warnings = j["w"].get<std::vector<std::string>>();
  if (j.contains("pc")) r.pieces = j["pc"].get<std::array<int, 2>>();
  if (j.contains("mo")) {
    const auto& mo = j["mo"];
    MotionTrace m;
    m.steps = mo["n"];
    m.max_depth = mo["d"];
    m.t_max_depth = mo["td"];
    m.t_min_distance = mo["tc"];
    m.series = mo["s"].get<std::vector<std::pair<double, double>>>();
    if (mo.contains("c")) m.min_distance = mo["c"].get<double>();
    r.motion = m;
  }
  return r;
}

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
  out.settings_hash = settings_hash(options.solver, options.tolerance, scene.checks);
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
  const auto pair_checks = pair_checks_of(parts, checks);

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
