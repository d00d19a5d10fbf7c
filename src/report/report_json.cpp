#include "report/report_json.h"

#include <cstdio>

#include "batch/fingerprint.h"

namespace pd {

using json = nlohmann::ordered_json;

int Summary::exit_code() const {
  if (error > 0 || undecided > 0 || part_errors > 0 || unchecked > 0) return 3;
  return interference > 0 || clearance_violation > 0 ? 1 : 0;
}

Summary summarize(const RunResult& r) {
  Summary s;
  s.parts = static_cast<long>(r.parts.size());
  for (const Part& p : r.parts) s.part_errors += p.error ? 1 : 0;
  s.all_pairs = r.all_pairs;
  s.culled = r.culled;
  s.unchecked = r.unchecked;
  s.candidates = static_cast<long>(r.pairs.size());
  for (const auto& what : r.simulated) s.clearance_checked |= what == "clearance";
  for (const PairResult& p : r.pairs) {
    switch (p.status) {
      case Status::kSeparated:
        ++s.separated;
        break;
      case Status::kFalsePositive:
        ++s.false_positive;
        break;
      case Status::kInterference:
        ++s.interference;
        break;
      case Status::kError:
        ++s.error;
        break;
      case Status::kClearanceViolation:
        ++s.clearance_violation;
        break;
      case Status::kUndecided:
        ++s.undecided;
        break;
    }
  }
  return s;
}

json pair_json(const PairResult& r, const std::vector<Part>& parts) {
  json j = {{"a", parts[r.a].id},
            {"b", parts[r.b].id},
            {"fingerprint", pair_fingerprint(parts[r.a].id, parts[r.b].id)},
            {"status", status_name(r.status)}};
  if (r.status == Status::kError) {
    j["error"] = r.error;
  } else {
    j["depth"] = r.depth;
    j["direction"] = {r.direction.x() + 0.0, r.direction.y() + 0.0,
                      r.direction.z() + 0.0};  // no -0
    j["margin"] = r.margin;
    if (r.distance) j["distance"] = *r.distance;
    j["depth_source"] = r.depth_source;
    if (r.hull_depth) j["hull_depth"] = *r.hull_depth;
    if (r.depth_bounds) j["depth_bounds"] = *r.depth_bounds;
    if (r.confirmed) j["confirmed"] = *r.confirmed;
    if (r.pieces) j["pieces"] = *r.pieces;
    if (r.at) j["at"] = {r.at->x() + 0.0, r.at->y() + 0.0, r.at->z() + 0.0};
    if (!r.reason.empty()) j["reason"] = r.reason;
  }
  if (r.clearance_min && r.status != Status::kError) {
    json c = {{"min", *r.clearance_min}};
    if (r.distance) c["distance"] = *r.distance;
    j["clearance"] = c;
  }
  if (r.motion && r.status != Status::kError) {
    const MotionTrace& m = *r.motion;
    json mo = {{"steps", m.steps}, {"max_depth", m.max_depth}, {"t_max_depth", m.t_max_depth}};
    if (m.min_distance) {
      mo["min_distance"] = *m.min_distance;
      mo["t_min_distance"] = m.t_min_distance;
    }
    if (!m.series.empty()) {
      json ser = json::array();
      for (const auto& [t, v] : m.series) ser.push_back({t, v});
      mo["series"] = ser;
    }
    j["motion"] = mo;
  }
  j["method"] = r.method;
  if (!r.fallback.empty()) j["fallback"] = r.fallback;
  if (!r.warnings.empty()) j["warnings"] = r.warnings;
  j["stats"] = {{"local_solves", r.stats.local_solves},
                {"distinct_optima", r.stats.distinct_optima},
                {"alpha_evaluations", r.stats.alpha_evaluations},
                {"ipopt_calls", r.stats.ipopt_calls},
                {"ipopt_iterations", r.stats.ipopt_iterations},
                {"ipopt_failures", r.stats.ipopt_failures},
                {"stop_reason", stop_reason_name(r.stats.stop_reason)}};
  j["time_ms"] = r.time_ms;
  if (r.reused) j["reused"] = true;
  return j;
}

json shard_json(const ShardManifest& m) {
  return {{"index", m.shard.index},
          {"total", m.shard.total},
          {"parts_total", m.parts_total},
          {"pairs_total", m.pairs_total},
          {"pairs_planned", m.pairs_planned},
          {"pairs_checked", m.pairs_checked},
          {"listed", m.listed},
          {"vertices_loaded", m.vertices_loaded},
          {"vertices_total", m.vertices_total},
          {"part_index", m.part_index},
          {"owned", m.owned}};
}

json summary_json(const Summary& s) {
  json j = {{"parts", s.parts},
            {"part_errors", s.part_errors},
            {"pairs", s.all_pairs},
            {"culled", s.culled},
            {"unchecked", s.unchecked},
            {"candidate_pairs", s.candidates},
            {"separated", s.separated},
            {"false_positive", s.false_positive},
            {"interference", s.interference},
            {"error", s.error},
            {"undecided", s.undecided},
            {"clearance_violation", s.clearance_violation},
            {"exit_code", s.exit_code()}};
  if (!s.clearance_checked) j.erase("clearance_violation");
  return j;
}

json report_json(const ReportContext& ctx, const RunResult& r) {
  json parts = json::array();
  for (size_t k = 0; k < r.parts.size(); ++k) {
    const Part& p = r.parts[k];
    json j = {{"id", p.id},
              {"source", p.source},
              {"vertices", p.vertex_count},
              {"hull_vertices", p.hull_vertex_count()},
              {"pieces", p.decomposition ? p.decomposition->pieces.size() : p.pieces.size()},
              {"warnings", p.warnings}};
    if (k < r.part_hashes.size()) j["content_hash"] = r.part_hashes[k];
    if (p.convex) j["convex"] = *p.convex;
    if (p.decomposition) {
      j["decomposition_seconds"] = p.decomposition->seconds;
      j["cached"] = p.decomposition->cached;
      if (!p.decomposition->complete) j["decomposition_note"] = p.decomposition->note;
    }
    if (p.error) j["error"] = *p.error;
    parts.push_back(j);
  }
  json pairs = json::array();
  for (const PairResult& p : r.pairs) pairs.push_back(pair_json(p, r.parts));
  const SolverSettings& s = ctx.solver;
  json method = {{"name", method_name(s.method)}, {"seed", s.seed}};
  if (s.method == Method::kMlsl)
    method.update({{"samples", s.samples},
                   {"reduced", s.reduced},
                   {"sigma", s.sigma},
                   {"tau", s.tau},
                   {"link_scale", s.link_scale}});
  if (s.method == Method::kMlslPaper)
    method.update({{"N", s.paper_n}, {"M", s.paper_m}, {"sigma", s.sigma}, {"tau", s.tau}});
  if (s.method == Method::kGrid) method["grid"] = s.grid;
  if (s.method == Method::kGsLocal) method["gs_local"] = s.gs_local;
  json doc = {{"tool", {{"name", "pdcheck"}, {"version", PDCHECK_VERSION}}},
              {"report_version", 1},
              {"scene", ctx.scene_path},
              {"units", ctx.units},
              {"tolerance", ctx.tolerance},
              {"method", method},
              {"direction_convention",
               "depth_source hull: moving part b by depth * direction separates the pair, and "
               "for separated pairs direction is a separating-plane normal pointing from a to b; "
               "thickness: moving b along direction thins the overlap at `at` (no separating "
               "move); surface, vertex: moving b by depth * direction lifts the deepest point "
               "out"},
              {"simulated", r.simulated},
              {"summary", summary_json(summarize(r))},
              {"seconds", r.seconds},
              {"stage_seconds",
               {{"load", ctx.load_seconds},
                {"parts", r.stages.parts},
                {"broad_phase", r.stages.broad_phase},
                {"solve", r.stages.solve},
                {"refine", r.stages.refine}}}};
  if (!r.scene_hash.empty())
    doc["hashes"] = {{"scene", r.scene_hash}, {"settings", r.settings_hash}};
  if (r.shard) doc["shard"] = shard_json(*r.shard);
  doc["parts"] = parts;
  doc["pairs"] = pairs;
  return doc;
}

std::string summary_line(const Summary& s, double seconds) {
  char buf[512];
  std::snprintf(
      buf, sizeof buf,
      "pdcheck: %ld parts, %ld candidate pairs (%ld culled%s): %ld interference, %s%ld "
      "false_positive, %ld separated, %s%ld error%s in %.2f s",
      s.parts, s.candidates, s.culled,
      s.unchecked ? (", " + std::to_string(s.unchecked) + " unchecked").c_str() : "",
      s.interference,
      s.clearance_checked
          ? (std::to_string(s.clearance_violation) + " clearance_violation, ").c_str()
          : "",
      s.false_positive, s.separated,
      s.undecided ? (std::to_string(s.undecided) + " undecided, ").c_str() : "", s.error,
      s.part_errors ? (", " + std::to_string(s.part_errors) + " part(s) unusable").c_str() : "",
      seconds);
  return buf;
}

}  // namespace pd
