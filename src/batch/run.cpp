#include "batch/run.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>

#include "batch/broad_phase.h"
#include "batch/content_hashes.h"
#include "batch/motion_sweep.h"
#include "batch/pair_solve.h"
#include "batch/progress.h"
#include "batch/refine.h"
#include "work_queue.h"

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
    plan = plan_scene(scene, options.shard->total, options.jobs, options.load_timeout);
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
        {options.cache_dir, &file_hashes}, options.load_memory_mb);
    progress.finish();
  }
  for (size_t k = 0; k < out.parts.size(); ++k)
    out.part_hashes.push_back(hashes[plan ? loaded[k] : k]);
  out.stages.parts = lap(t);
  const std::vector<Part>& parts = out.parts;
  const int n = static_cast<int>(parts.size());
  const Checks& checks = scene.checks;
  out.simulated = {"interference"};
  if (checks.clearance) out.simulated.push_back("clearance");
  if (checks.motion) out.simulated.push_back("motion");
  // Clearance per pair: the scene's minimum, or a named pair's own.
  std::map<std::pair<std::string, std::string>, double> own_clearance;
  double reach = 0.0;  // how far apart boxes may be and still need a check
  if (checks.clearance) {
    reach = checks.clearance->min;
    for (const auto& e : checks.clearance->pairs) {
      own_clearance[{std::min(e.a, e.b), std::max(e.a, e.b)}] = e.min;
      reach = std::max(reach, e.min);
    }
  }
  auto pair_checks = [&](int a, int b) {
    PairChecks pc;
    if (checks.clearance) {
      const auto it = own_clearance.find(
          {std::min(parts[a].id, parts[b].id), std::max(parts[a].id, parts[b].id)});
      pc.clearance = it == own_clearance.end() ? checks.clearance->min : it->second;
    }
    if (checks.motion && (parts[a].motion || parts[b].motion)) pc.motion = &*checks.motion;
    return pc;
  };

  std::vector<std::pair<int, int>> pairs;
  if (plan) {
    // This shard's planned pairs, kept when their hull boxes touch: exactly the
    // unsharded broad phase's decision (boxes_touch), pair by pair.
    const int shard = options.shard->index - 1;
    std::vector<int> local(scene.parts.size(), -1);
    for (size_t k = 0; k < loaded.size(); ++k) local[loaded[k]] = static_cast<int>(k);
    std::vector<Aabb> boxes(n);
    for (int k = 0; k < n; ++k)
      if (!parts[k].error)
        boxes[k] = checks.motion ? swept_box(parts[k], checks.motion->grid) : parts[k].box;
    ShardManifest m;
    m.shard = *options.shard;
    m.parts_total = static_cast<long>(scene.parts.size());
    m.part_index = loaded;
    for (int k : loaded)
      if (plan->owner[k] == shard) m.owned.push_back(k);
    for (const Part& p : parts) m.vertices_loaded += p.vertex_count;
    m.vertices_total = plan->vertices_total;
    for (size_t p = 0; p < plan->pairs.size(); ++p) {
      if (plan->pair_shard[p] != shard) continue;
      ++m.pairs_planned;
      const int a = local[plan->pairs[p].first], b = local[plan->pairs[p].second];
      if (plan->listed) {
        pairs.emplace_back(a, b);
      } else if (parts[a].error || parts[b].error) {
        ++out.unchecked;
      } else if (boxes_touch(boxes[a], boxes[b], reach)) {
        pairs.emplace_back(a, b);
      } else {
        ++out.culled;
      }
    }
    const long all = m.parts_total * (m.parts_total - 1) / 2;
    m.pairs_total = plan->listed ? static_cast<long>(plan->pairs.size()) : all;
    out.all_pairs = m.pairs_planned;
    m.pairs_checked = static_cast<long>(pairs.size());
    m.listed = plan->listed;
    out.shard = std::move(m);
  } else if (scene.pairs) {
    std::map<std::string, int> index;
    for (int k = 0; k < n; ++k) index[parts[k].id] = k;
    for (const auto& [a, b] : *scene.pairs) {
      const int ia = index.at(a), ib = index.at(b);
      pairs.emplace_back(std::min(ia, ib), std::max(ia, ib));
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    out.all_pairs = static_cast<long>(pairs.size());
  } else {
    out.all_pairs = static_cast<long>(n) * (n - 1) / 2;
    std::vector<Aabb> boxes;
    std::vector<int> usable;
    for (int k = 0; k < n; ++k) {
      if (parts[k].error) continue;
      usable.push_back(k);
      // A moving part is culled by the box it sweeps over the time grid.
      boxes.push_back(checks.motion ? swept_box(parts[k], checks.motion->grid) : parts[k].box);
    }
    // A part that failed to load is reported with its reason in the part list
    // (and the exit code); its pairs cannot be formed without geometry.
    for (const auto& [i, j] : overlapping_boxes(boxes, reach))
      pairs.emplace_back(usable[i], usable[j]);
    const long usable_pairs = static_cast<long>(usable.size()) * (long(usable.size()) - 1) / 2;
    out.unchecked = out.all_pairs - usable_pairs;  // not the broad phase's doing
    out.culled = usable_pairs - static_cast<long>(pairs.size());
  }

  out.stages.broad_phase = lap(t);
  out.pairs.resize(pairs.size());
  // Largest pairs first (by the work of one support evaluation): no worker
  // idles at the end on a long tail.
  // --reuse: an unchanged pair keeps its old result (nonconvex parts' pairs are
  // solved again: their refinement runs after the hull stage).
  std::vector<size_t> order;
  for (size_t k = 0; k < pairs.size(); ++k) {
    const auto [a, b] = pairs[k];
    std::optional<PairResult> prior;
    if (options.reuse && !parts[a].refinable() && !parts[b].refinable())
      prior = prior_result(*options.reuse, out.settings_hash, a, parts[a].id, out.part_hashes[a], b,
                           parts[b].id, out.part_hashes[b]);
    if (!prior) {
      order.push_back(k);
      continue;
    }
    out.pairs[k] = *prior;
    ++out.reused;
    if (options.on_pair) options.on_pair(out.pairs[k], parts);
  }
  std::vector<long> hull_size(n);
  for (int k = 0; k < n; ++k) hull_size[k] = parts[k].hull_vertex_count();
  auto cost = [&](size_t k) { return hull_size[pairs[k].first] * hull_size[pairs[k].second]; };
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t x, size_t y) { return cost(x) > cost(y); });

  Progress progress(order.size(), options.quiet, "pairs");
  std::unique_ptr<IpoptLocalSolver> ipopt;  // created in each worker on first use
  // Fault injection for the crash-isolation test: the worker that takes the
  // named pair dies as a solver crash would.
  const char* crash = std::getenv("PDCHECK_TEST_CRASH_PAIR");
  // And for the signal and broken-pipe tests: every pair takes this long.
  const char* slow = std::getenv("PDCHECK_TEST_PAIR_SLEEP_MS");
  const long slow_ms = slow ? std::atol(slow) : 0;
  auto task = [&](size_t k) {
    if (!ipopt) ipopt = std::make_unique<IpoptLocalSolver>();
    const auto [a, b] = pairs[k];
    if (crash && parts[a].id + ":" + parts[b].id == crash) std::abort();
    if (slow_ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(slow_ms));
    return encode_pair_result(solve_part_pair(a, parts[a], b, parts[b], options.solver,
                                              options.tolerance, *ipopt, pair_checks(a, b)));
  };
  auto done = [&](size_t k, bool ok, const std::string& payload) {
    PairResult r = pair_result_from_worker(ok, payload, pairs[k].first, pairs[k].second,
                                                 method_name(options.solver.method));
    note_hull_stage(r, parts[r.a], parts[r.b]);
    out.pairs[k] = r;
    // A pair the refinement takes on is reported when it is decided.
    if (options.on_pair && !needs_refinement(r, parts[r.a], parts[r.b])) options.on_pair(r, parts);
    progress.tick();
  };
  run_work_queue(order, {options.jobs, options.pair_timeout, options.on_warning}, task, done);
  progress.finish();
  out.stages.solve = lap(t);
  refine_nonconvex_pairs(out.parts, pairs, out.pairs, options, pair_checks);
  out.stages.refine = lap(t);
  out.seconds = std::chrono::duration<double>(t - t0).count();
  return out;
}

}  // namespace pd
