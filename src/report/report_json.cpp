#include "report/report_json.h"

#include <cstdio>
#include <type_traits>

#include "report/finding_text.h"
#include "report/rules_report.h"
#include "results/codec.h"

namespace pd {

using json = nlohmann::ordered_json;

Summary summarize(const RunResult& r) {
  Summary s;
  s.parts = static_cast<long>(r.parts.size());
  for (const Part& p : r.parts) s.part_errors += p.error ? 1 : 0;
  s.all_pairs = r.all_pairs;
  s.culled = r.culled;
  s.unchecked = r.unchecked;
  s.candidates = static_cast<long>(r.pairs.size());
  for (const auto& what : r.simulated) s.clearance_checked |= what == "clearance";
  for (const PairResult& p : r.pairs) s.add(p.status);
  if (r.rules) {
    s.rules_given = true;
    s.out_of_scope = r.rules->out_of_scope;
    s.ignored = r.rules->ignored;
  }
  s.reuse = r.reuse;
  return s;
}

json pair_json(const PairResult& r, const std::vector<Part>& parts) {
  return pair_to_report(r, parts[r.a].id, parts[r.b].id);
}

namespace {

// A shard's manifest (docs/report-format.md, "shard"); checked and pairs
// counts are the shard's summary.
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

}  // namespace

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
  if (s.reuse) j["reuse"] = {{"reused", s.reuse->reused}, {"solved", s.reuse->solved}};
  if (s.rules_given) {
    // After the culled pairs: the candidates the rules kept out of the check.
    json k;
    for (auto& [key, v] : j.items()) {
      k[key] = v;
      if (key == "culled") {
        k["out_of_scope"] = s.out_of_scope;
        k["ignored"] = s.ignored;
      }
    }
    j = std::move(k);
  }
  return j;
}

json method_json(const SolverSettings& s) {
  json method = json::object();
  for_each_setting(s, [&](const Setting& setting, const auto& value) {
    if (!setting.reported_for(s.method)) return;
    if constexpr (std::is_same_v<std::decay_t<decltype(value)>, Method>)
      method[setting.report_key] = method_name(value);
    else
      method[setting.report_key] = value;
  });
  return method;
}

namespace {

// The report's view of part k (results/part_result.h).
PartResult part_result(const RunResult& r, size_t k) {
  const Part& p = r.parts[k];
  PartResult out;
  out.id = p.id;
  out.source = p.source;
  out.vertices = static_cast<long>(p.vertex_count);
  out.hull_vertices = static_cast<long>(p.hull_vertex_count());
  out.pieces =
      static_cast<long>(p.decomposition ? p.decomposition->pieces.size() : p.pieces.size());
  out.warnings = p.warnings;
  out.resolution = p.resolution;
  if (!p.error) {  // where the part is: exports aim at it (--bcf), also after a merge
    out.box_min = p.box.lo;
    out.box_max = p.box.hi;
  }
  if (k < r.part_hashes.size()) out.content_hash = r.part_hashes[k];
  out.convex = p.convex;
  if (p.brep) {
    out.tessellation_deflection = p.brep->tessellation.deflection;
    out.tessellation_sag = p.brep->tessellation.sag;
    out.tessellation_basis = sag_basis_name(p.brep->tessellation.basis);
  }
  if (p.sag) {
    out.sag_concave = p.sag->measured.concave;
    out.sag_convex = p.sag->measured.convex;
    out.sag_declared = p.sag->declared;
  }
  if (p.decomposition) {
    out.decomposition_seconds = p.decomposition->seconds;
    out.cached = p.decomposition->cached;
    if (!p.decomposition->complete) out.decomposition_note = p.decomposition->note;
  }
  if (k < r.labels.size()) {
    out.tags = r.labels[k].tags;
    out.group = r.labels[k].group;
    if (r.rules) out.sets = r.labels[k].sets;
  }
  out.error = p.error;
  return out;
}

}  // namespace

json tolerance_json(const ReportContext& ctx) {
  return ctx.auto_tolerance ? json("auto") : json(ctx.tolerance);
}

std::string tolerance_words(const ReportContext& ctx) {
  return ctx.auto_tolerance ? "auto" : short_number(ctx.tolerance) + " " + ctx.units;
}

json report_json(const ReportContext& ctx, const RunResult& r) {
  json parts = json::array();
  for (size_t k = 0; k < r.parts.size(); ++k) parts.push_back(part_to_report(part_result(r, k)));
  json pairs = json::array();
  for (const PairResult& p : r.pairs) pairs.push_back(pair_json(p, r.parts));
  const json method = method_json(ctx.solver);
  json doc = {{"tool", {{"name", "pdcheck"}, {"version", PDCHECK_VERSION}}},
              {"report_version", 1},
              {"scene", ctx.scene_path},
              {"units", ctx.units},
              {"tolerance", tolerance_json(ctx)},
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
                {"refine", r.stages.refine},
                {"exact", r.stages.exact}}}};
  if (ctx.auto_tolerance) {
    json a = json::object();
    if (ctx.auto_tolerance->min) a["min"] = *ctx.auto_tolerance->min;
    if (ctx.auto_tolerance->max) a["max"] = *ctx.auto_tolerance->max;
    doc["tolerance_auto"] = a;
  }
  if (!r.scene_hash.empty())
    doc["hashes"] = {{"scene", r.scene_hash}, {"settings", r.settings_hash}};
  if (r.rules) {
    if (doc.contains("hashes")) doc["hashes"]["rules"] = r.rules->hash;
    doc["stage_seconds"]["rules"] = r.rules->seconds;
  }
  if (r.shard) doc["shard"] = shard_json(*r.shard);
  if (r.rules) doc["rules"] = rules_json(*r.rules);
  doc["parts"] = parts;
  doc["pairs"] = pairs;
  return doc;
}

std::string reuse_line(const ReuseCounts& c, const std::string& from) {
  std::string t = "pdcheck: " + std::to_string(c.reused) + " pair(s) reused from " + from;
  long solved = 0;
  for (const auto& [why, n] : c.solved) solved += n;
  if (!solved) return t;
  t += "; " + std::to_string(solved) + " solved again:";
  const char* sep = " ";
  for (const auto& [why, n] : c.solved) {
    const std::string words = why == "settings"       ? "under other settings"
                              : why == "part_changed" ? "with a changed or new part"
                              : why == "new_pair"     ? "not among its pairs"
                              : why == "error"        ? "an error there"
                              : why == "pair_checks"  ? "under another pair tolerance or clearance"
                                                      : why;
    t += sep + std::to_string(n) + " " + words;
    sep = ", ";
  }
  return t;
}

std::string summary_line(const Summary& s, double seconds) {
  char buf[512];
  std::snprintf(
      buf, sizeof buf,
      "pdcheck: %ld parts, %ld candidate pairs (%ld culled%s%s): %ld interference, %s%ld "
      "false_positive, %ld separated, %s%ld error%s in %.2f s",
      s.parts, s.candidates, s.culled,
      s.rules_given ? (", " + std::to_string(s.out_of_scope) + " out of scope, " +
                       std::to_string(s.ignored) + " ignored")
                          .c_str()
                    : "",
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
