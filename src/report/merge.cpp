#include "report/merge.h"

#include <algorithm>
#include <map>

#include "batch/broad_phase.h"
#include "report/groups_json.h"
#include "report/json_input.h"
#include "report/report_json.h"
#include "report/review.h"
#include "report/review_json.h"
#include "report/rules_report.h"
#include "results/codec.h"
#include "results/fingerprint.h"

namespace pd {

using json = nlohmann::ordered_json;

ShardReport read_shard_report(const std::string& path) {
  std::string text;
  try {
    text = read_input_file(path);
  } catch (const ReportInputError& e) {
    throw MergeError(e.what());
  }
  ShardReport r{path, {}};
  try {
    r.doc = json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw MergeError(path + ": not a JSON report (" + e.what() + ")");
  }
  if (!r.doc.is_object() || !r.doc.contains("shard") || !r.doc["shard"].is_object())
    throw MergeError(path + ": $.shard: missing: not a shard report (written without --shard?)");
  return r;
}

namespace {

std::string text_of(const json& j) {
  return j.is_string() ? j.get<std::string>() : j.dump();
}

// The same value in every shard, or a MergeError naming the two that differ.
void same(const std::vector<ShardReport>& shards, const std::string& what,
          const std::function<json(const json&)>& get) {
  const json first = get(shards[0].doc);
  for (size_t k = 1; k < shards.size(); ++k) {
    const json v = get(shards[k].doc);
    if (v != first)
      throw MergeError("shards of different runs: " + what + " is " + text_of(first) + " in " +
                       shards[0].path + " but " + text_of(v) + " in " + shards[k].path);
  }
}

// Every shard of the same run: tool, hashes, shard count, units, tolerance,
// method, checks and totals.
void check_same_run(const std::vector<ShardReport>& shards) {
  try {
    same(shards, "the tool version", [](const json& d) { return d.at("tool").at("version"); });
    same(shards, "the scene content hash ($.hashes.scene)",
         [](const json& d) { return d.at("hashes").at("scene"); });
    same(shards, "the settings hash ($.hashes.settings)",
         [](const json& d) { return d.at("hashes").at("settings"); });
    same(shards, "the rules hash ($.hashes.rules)", [](const json& d) {
      return d.at("hashes").contains("rules") ? d["hashes"]["rules"] : json();
    });
    same(shards, "the shard count ($.shard.total)",
         [](const json& d) { return d.at("shard").at("total"); });
    same(shards, "$.units", [](const json& d) { return d.at("units"); });
    same(shards, "$.tolerance", [](const json& d) { return d.at("tolerance"); });
    same(shards, "$.method", [](const json& d) { return d.at("method"); });
    same(shards, "$.simulated", [](const json& d) { return d.at("simulated"); });
    same(shards, "$.shard.parts_total",
         [](const json& d) { return d.at("shard").at("parts_total"); });
    same(shards, "$.shard.pairs_total",
         [](const json& d) { return d.at("shard").at("pairs_total"); });
  } catch (const nlohmann::json::exception& e) {
    throw MergeError(std::string("not a shard report: ") + e.what());
  }
}

// Each shard once: a duplicated shard would count its pairs twice, a missing one
// would pass its pairs as clean.
void check_each_shard_once(const std::vector<ShardReport>& shards, long total) {
  std::map<long, std::string> by_index;
  for (const ShardReport& s : shards) {
    const long k = s.doc["shard"].at("index").get<long>();
    const auto [it, fresh] = by_index.emplace(k, s.path);
    if (!fresh)
      throw MergeError("shard " + std::to_string(k) + "/" + std::to_string(total) +
                       " given twice: " + it->second + " and " + s.path);
  }
  std::string missing;
  for (long k = 1; k <= total; ++k)
    if (!by_index.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
  if (!missing.empty())
    throw MergeError("shard(s) " + missing + " of " + std::to_string(total) + " missing (" +
                     std::to_string(shards.size()) + " of " + std::to_string(total) + " given)");
}

// The scene's parts, each from the shard that owns it, in scene order.
std::vector<json> owned_parts(const std::vector<ShardReport>& shards, long n) {
  std::vector<json> parts(n);
  std::vector<std::string> owner(n);
  for (const ShardReport& s : shards) {
    const json& m = s.doc["shard"];
    std::map<long, size_t> listed;  // scene index -> position in this report's parts
    const json& index = m.at("part_index");
    for (size_t k = 0; k < index.size(); ++k) listed[index[k].get<long>()] = k;
    for (const json& o : m.at("owned")) {
      const long k = o.get<long>();
      if (k < 0 || k >= n || !listed.count(k))
        throw MergeError(s.path + ": $.shard.owned: part index " + std::to_string(k) +
                         " is not among its parts");
      if (!owner[k].empty())
        throw MergeError("part index " + std::to_string(k) + " reported by both " + owner[k] +
                         " and " + s.path + ": the shards were planned differently");
      owner[k] = s.path;
      parts[k] = s.doc.at("parts").at(listed[k]);
    }
  }
  for (long k = 0; k < n; ++k) {
    if (owner[k].empty())
      throw MergeError("part index " + std::to_string(k) + " is reported by no shard");
  }
  // A part decomposed by a shard that does not own it (its pair needed it there).
  for (const ShardReport& s : shards) {
    const json& index = s.doc["shard"]["part_index"];
    for (size_t k = 0; k < index.size(); ++k) {
      const long i = index[k].get<long>();
      const json& p = s.doc["parts"][k];
      if (p.contains("decomposition_seconds") && !parts[i].contains("decomposition_seconds"))
        parts[i] = p;
      // A part whose convexity a pair of another shard measured
      // (batch/convexity_on_demand.h): the same value wherever it was measured.
      if (p.contains("convex") && !parts[i].contains("convex")) parts[i]["convex"] = p["convex"];
    }
  }
  return parts;
}

struct Entry {
  int a, b;
  const json* pair;
  const std::string* path;
};

// Every shard's pairs, in the unsharded run's (a, b) order; a pair twice is refused.
std::vector<Entry> pair_entries(const std::vector<ShardReport>& shards,
                                const std::vector<json>& parts) {
  std::map<std::string, int> id_index;
  for (size_t k = 0; k < parts.size(); ++k)
    id_index[parts[k].at("id").get<std::string>()] = static_cast<int>(k);

  std::vector<Entry> entries;
  for (const ShardReport& s : shards)
    for (const json& p : s.doc.at("pairs")) {
      const auto ia = id_index.find(p.at("a").get<std::string>());
      const auto ib = id_index.find(p.at("b").get<std::string>());
      if (ia == id_index.end() || ib == id_index.end())
        throw MergeError(s.path + ": pair " + p.at("a").dump() + ", " + p.at("b").dump() +
                         " names a part no shard reports");
      entries.push_back(
          {std::min(ia->second, ib->second), std::max(ia->second, ib->second), &p, &s.path});
    }
  std::sort(entries.begin(), entries.end(),
            [](const Entry& x, const Entry& y) { return std::tie(x.a, x.b) < std::tie(y.a, y.b); });
  for (size_t k = 1; k < entries.size(); ++k)
    if (entries[k].a == entries[k - 1].a && entries[k].b == entries[k - 1].b)
      throw MergeError("pair " + entries[k].pair->at("a").dump() + ", " +
                       entries[k].pair->at("b").dump() + " checked by both " +
                       *entries[k - 1].path + " and " + *entries[k].path);

  return entries;
}

// The parts (id, source, vertices, warnings, error, box; no geometry) and pairs of
// the merged run, for its review and the other writers.
RunResult merged_run(const json& first, const std::vector<json>& parts,
                     const std::vector<Entry>& entries) {
  RunResult run;
  run.simulated = first.at("simulated").get<std::vector<std::string>>();
  for (const json& j : parts) {
    PartResult r;
    try {
      r = part_from_report(j);
    } catch (const std::exception& ex) {
      throw MergeError("part " + j.value("id", json("?")).dump() + ": " + ex.what());
    }
    Part p;
    p.id = r.id;
    p.source = r.source;
    p.vertex_count = r.vertices;
    p.warnings = r.warnings;
    p.error = r.error;
    if (r.box_min && r.box_max) p.box = {*r.box_min, *r.box_max};  // what --bcf aims at
    run.parts.push_back(std::move(p));
  }
  for (const Entry& e : entries) {
    try {
      run.pairs.push_back(pair_from_report(*e.pair, e.a, e.b));
    } catch (const std::exception& ex) {
      throw MergeError(*e.path + ": pair " + e.pair->at("a").dump() + ", " +
                       e.pair->at("b").dump() + ": " + ex.what());
    }
  }
  return run;
}

// The summary as one run counts it: from the scene's totals, the pairs of
// unusable parts are unchecked and the rest culled or checked (a pair list has
// no broad phase).
Summary merged_summary(const json& first, const RunResult& run, long n,
                       const std::optional<json>& rules) {
  Summary s = summarize(run);
  s.all_pairs = first["shard"]["pairs_total"].get<long>();
  if (rules) {  // the shards' candidates the rules kept out, summed
    s.rules_given = true;
    s.out_of_scope = rules->at("out_of_scope").get<long>();
    s.ignored = rules->at("ignored").get<long>();
  }
  if (!first["shard"].value("listed", false)) {
    const long usable = n - s.part_errors;
    const long usable_pairs = pair_count(usable);
    s.unchecked = s.all_pairs - usable_pairs;
    s.culled = usable_pairs - s.candidates - s.out_of_scope - s.ignored;
  }
  return s;
}

// The shards' rules sections as one run's (report/rules_report.h), when they have rules.
std::optional<json> merged_rules(const std::vector<ShardReport>& shards) {
  if (!shards[0].doc.contains("rules")) return std::nullopt;
  std::vector<const json*> sections;
  for (const ShardReport& s : shards) {
    if (!s.doc.contains("rules"))
      throw MergeError(s.path + ": $.rules: missing, but " + shards[0].path + " has rules");
    sections.push_back(&s.doc["rules"]);
  }
  try {
    return merge_rules_sections(sections);
  } catch (const nlohmann::json::exception& e) {
    throw MergeError(std::string("$.rules: not a rules section of this version: ") + e.what());
  }
}

// The shards' times summed into the merged report's `seconds` and
// `stage_seconds`; returns the seconds.
double add_shard_times(const std::vector<ShardReport>& shards, json& doc) {
  double seconds = 0.0;
  json stages = shards[0].doc.at("stage_seconds");
  for (auto& [key, v] : stages.items()) v = 0.0;
  for (const ShardReport& sh : shards) {
    seconds += sh.doc.at("seconds").get<double>();
    for (auto& [key, v] : stages.items())
      v = v.get<double>() + sh.doc["stage_seconds"].value(key, 0.0);
  }
  doc["seconds"] = seconds;
  doc["stage_seconds"] = stages;
  return seconds;
}

}  // namespace

Merged merge_shard_reports(const std::vector<ShardReport>& shards, const ReviewOptions& review) {
  if (shards.empty()) throw MergeError("no shard reports given");
  check_same_run(shards);
  const json& first = shards[0].doc;
  check_each_shard_once(shards, first["shard"]["total"].get<long>());
  const long n = first["shard"]["parts_total"].get<long>();
  const std::vector<json> parts = owned_parts(shards, n);
  const std::vector<Entry> entries = pair_entries(shards, parts);

  // The run as one run would have it: its counts, then its review.
  Merged out;
  out.run = merged_run(first, parts, entries);
  RunResult& run = out.run;
  for (const ShardReport& shard : shards) {  // shards run with --reuse: their counts, summed
    const json& s = shard.doc.at("summary");
    if (!s.contains("reuse")) continue;
    if (!run.reuse) run.reuse.emplace();
    run.reuse->reused += s["reuse"].at("reused").get<long>();
    for (const auto& [why, n] : s["reuse"].at("solved").items())
      run.reuse->solved[why] += n.get<long>();
  }
  const std::optional<json> rules = merged_rules(shards);
  const Summary s = merged_summary(first, run, n, rules);
  const bool listed = first["shard"].value("listed", false);
  out.review_options = review;
  if (rules) {  // the expected-contact rules, as the shards' reports give them
    out.expected =
        std::make_shared<ExpectedRules>(expected_rules_of_report(*rules, shards[0].path));
    out.review_options.expected = out.expected.get();
  }
  // Tolerance auto: each pair's own band is in its entry ("tolerance": "auto").
  const bool auto_tolerance = first.at("tolerance") == "auto";
  out.review_options.tolerance = auto_tolerance ? 0.0 : first.at("tolerance").get<double>();
  out.review_options.units = first.at("units").get<std::string>();
  if (listed) {
    // A scene's pair list has no broad phase: its pairs of usable parts are
    // exactly the pairs reported, which is what the review asks of the list.
    out.review_options.listed.emplace();
    for (const Entry& e : entries)
      out.review_options.listed->insert(pair_fingerprint(run.parts[e.a].id, run.parts[e.b].id));
  }
  out.review = review_run(run, out.review_options, s.incomplete());

  out.doc = first;
  out.doc.erase("shard");
  if (rules) out.doc["rules"] = *rules;
  out.doc["summary"] = summary_json(s);
  const double seconds = add_shard_times(shards, out.doc);
  run.seconds = seconds;
  out.doc["parts"] = json(parts);
  json pairs = json::array();
  for (size_t k = 0; k < entries.size(); ++k) {
    json p = *entries[k].pair;
    add_pair_review(p, out.review.pairs[k]);
    pairs.push_back(std::move(p));
  }
  out.doc["pairs"] = std::move(pairs);
  out.doc["groups"] = groups_json(out.review.groups, run);  // the merged set's, as one run's
  add_run_review(out.doc, out.doc["summary"], out.review, out.review_options);
  out.context.scene_path = first.at("scene").get<std::string>();
  out.context.units = first.at("units").get<std::string>();
  out.context.tolerance = out.review_options.tolerance;
  if (auto_tolerance) {
    out.context.auto_tolerance = AutoTolerance{};
    const json a = first.value("tolerance_auto", json::object());
    if (a.contains("min")) out.context.auto_tolerance->min = a["min"].get<double>();
    if (a.contains("max")) out.context.auto_tolerance->max = a["max"].get<double>();
  }
  out.summary_line = summary_line(s, seconds);
  return out;
}

}  // namespace pd
