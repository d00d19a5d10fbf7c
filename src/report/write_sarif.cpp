// --sarif FILE: SARIF 2.1.0 for code-scanning views (GitHub). A rule per
// status, a result per finding, failed pair and gone baseline finding, keyed
// by the pair fingerprint (partialFingerprints) with baselineState and
// external suppressions. docs/ci.md.
#include <unistd.h>

#include <cctype>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "report/finding_text.h"
#include "report/writer.h"

namespace pd {

using json = nlohmann::ordered_json;

namespace {

struct Rule {
  Status status;
  const char* name;
  const char* description;
  const char* level;  ///< when the finding does not fail the run
};
const Rule kRules[] = {
    {Status::kInterference, "GenuineInterference",
     "Two parts overlap deeper than the tolerance: a genuine interference.", "warning"},
    {Status::kClearanceViolation, "ClearanceViolation",
     "Two parts are closer than the clearance the scene requires.", "warning"},
    {Status::kFalsePositive, "TessellationFalsePositive",
     "Two parts overlap by at most the tolerance: a discretization false positive.", "note"},
    {Status::kError, "PairNotChecked", "The pair could not be checked (the reason is given).",
     "error"},
    {Status::kUndecided, "PairUndecided",
     "The pair's certified depth bracket still straddles the tolerance: not decided within the "
     "work box (the bracket and the reason are given).",
     "error"},
};

int rule_index(Status s) {
  for (int k = 0; k < static_cast<int>(std::size(kRules)); ++k)
    if (kRules[k].status == s) return k;
  return -1;
}

/// A URI reference for a path: relative to the working directory when below
/// it (as a repository checkout is), else a file URI; RFC 3986 escaping.
std::string path_uri(const std::string& path) {
  namespace fs = std::filesystem;
  std::string p = path;
  bool absolute = fs::path(p).is_absolute();
  if (absolute) {
    std::error_code ec;
    const fs::path rel = fs::path(p).lexically_relative(fs::current_path(ec));
    if (!ec && !rel.empty() && *rel.begin() != "..") {
      p = rel.generic_string();
      absolute = false;
    }
  }
  static const char* kHex = "0123456789ABCDEF";
  std::string out = absolute ? "file://" : "";
  for (const unsigned char c : p) {
    if (std::isalnum(c) || c == '/' || c == '-' || c == '.' || c == '_' || c == '~') {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}

json locations(const std::vector<std::string>& files) {
  json locs = json::array();
  for (size_t k = 0; k < files.size(); ++k) {
    const std::string& f = files[k];
    if (f.empty() || f == "-" || (k > 0 && f == files[0])) continue;  // one entry per file
    locs.push_back({{"physicalLocation", {{"artifactLocation", {{"uri", path_uri(f)}}}}}});
  }
  return locs;
}

std::string part_file(const Part& p, const std::string& scene) {
  return p.source == "inline" ? scene : p.source;
}

json rule_json(const Rule& r, FailOn bar) {
  const bool fails = reaches_bar(bar, r.status) || not_decided(r.status);
  return {{"id", status_name(r.status)},
          {"name", r.name},
          {"shortDescription", {{"text", r.description}}},
          {"defaultConfiguration", {{"level", fails ? "error" : r.level}}}};
}

// A suppressed finding's SARIF suppression: a --suppressions entry, or an
// expected-contact rule of the scene's rules.
json suppression_json(const Suppression& s, const ReportInput& in) {
  json props = {
      {"file", s.rule.empty() ? in.review_options.suppressions->path : in.context.scene_path},
      {"entry", s.where}};
  if (!s.rule.empty()) props["rule"] = s.rule;
  if (!s.owner.empty()) props["owner"] = s.owner;
  if (!s.expires.empty()) props["expires"] = s.expires;
  if (s.max_depth) props["max_depth"] = *s.max_depth;
  return json::array({{{"kind", "external"}, {"justification", s.reason}, {"properties", props}}});
}

}  // namespace

std::string render_sarif(const ReportInput& in) {
  const RunResult& run = in.run;
  const Review& rv = in.review;
  const std::string& scene = in.context.scene_path;
  json rules = json::array();
  for (const Rule& r : kRules) rules.push_back(rule_json(r, rv.fail_on));

  json results = json::array();
  for (size_t k = 0; k < run.pairs.size(); ++k) {
    const PairResult& r = run.pairs[k];
    const PairReview& pr = rv.pairs[k];
    if (!is_finding(r.status) && !not_decided(r.status)) continue;
    const int rule = rule_index(r.status);
    const Part& a = run.parts[r.a];
    const Part& b = run.parts[r.b];
    json res = {
        {"ruleId", status_name(r.status)},
        {"ruleIndex", rule},
        {"level", not_decided(r.status) || pr.fails ? "error" : kRules[rule].level},
        {"message",
         {{"text", finding_text(r, run.parts, pr, in.context.units, in.context.tolerance)}}},
        {"locations", locations({part_file(a, scene), part_file(b, scene)})},
        {"partialFingerprints", {{"pdcheckPair/v1", pr.fingerprint}}}};
    if (pr.baseline_state) res["baselineState"] = baseline_state_name(*pr.baseline_state);
    if (pr.suppressed) res["suppressions"] = suppression_json(*pr.suppressed, in);
    json props = {{"a", a.id}, {"b", b.id}, {"status", status_name(r.status)}};
    if (r.duplicate) props["duplicate"] = true;
    if (r.status != Status::kError) {
      props["depth"] = r.depth;
      props["depth_source"] = r.depth_source;  // which quantity the depth is
      if (r.depth_bounds) props["depth_bounds"] = *r.depth_bounds;
      props["tolerance"] = r.tolerance ? json(*r.tolerance) : tolerance_json(in.context);
      props["units"] = in.context.units;
      props["direction"] = {r.direction.x() + 0.0, r.direction.y() + 0.0, r.direction.z() + 0.0};
    }
    res["properties"] = props;
    results.push_back(res);
  }
  // Baseline findings that are no findings now: absent ones pass; unknown
  // ones stay open (SARIF has no "unknown" baseline state: a property says it).
  std::map<std::string, const Part*> by_id;
  for (const Part& p : run.parts) by_id[p.id] = &p;
  for (const GoneFinding& g : rv.gone) {
    std::vector<std::string> files;
    for (const std::string* id : {&g.was.a, &g.was.b}) {
      const auto it = by_id.find(*id);
      if (it != by_id.end()) files.push_back(part_file(*it->second, scene));
    }
    const bool absent = g.state == BaselineState::kAbsent;
    Status was = Status::kInterference;
    for (const Rule& r : kRules)
      if (g.was.status == status_name(r.status)) was = r.status;
    json res = {{"ruleId", status_name(was)},
                {"ruleIndex", rule_index(was)},
                {"kind", absent ? "pass" : "open"},
                {"level", "none"},
                {"message",
                 {{"text", g.was.a + " / " + g.was.b + ": was " + g.was.status + " (depth " +
                               short_number(g.was.depth) + " " + in.context.units +
                               ") in the baseline; now " + baseline_state_name(g.state) + ": " +
                               g.reason}}},
                {"locations", locations(files)},
                {"partialFingerprints", {{"pdcheckPair/v1", g.was.fingerprint}}}};
    if (absent) res["baselineState"] = "absent";
    res["properties"] = {
        {"a", g.was.a}, {"b", g.was.b}, {"baselineState", baseline_state_name(g.state)}};
    results.push_back(res);
  }

  json notes = json::array();
  for (const Part& p : run.parts)
    if (p.error)
      notes.push_back({{"level", "error"},
                       {"message", {{"text", "part " + p.id + " could not be used: " + *p.error}}},
                       {"locations", locations({part_file(p, scene)})}});
  for (const SuppressionIssue& i : rv.suppression_issues)
    notes.push_back(
        {{"level", i.fails ? "error" : "warning"},
         {"message",
          {{"text", in.review_options.suppressions->path + " " + i.entry->where + " (" +
                        i.entry->a + " / " + i.entry->b + "): " + i.kind + ": " + i.detail}}}});
  json invocation = {{"executionSuccessful", rv.exit_code != kExitIncomplete},
                     {"exitCode", rv.exit_code}};
  if (!notes.empty()) invocation["toolExecutionNotifications"] = notes;

  json driver = {{"name", "pdcheck"},
                 {"version", PDCHECK_VERSION},
                 {"semanticVersion", PDCHECK_VERSION},
                 {"rules", rules}};
  json sarif_run = {{"tool", {{"driver", driver}}},
                    {"invocations", json::array({invocation})},
                    {"results", results},
                    {"properties",
                     {{"scene", scene},
                      {"units", in.context.units},
                      {"tolerance", tolerance_json(in.context)},
                      {"fail_on", fail_on_name(rv.fail_on)}}}};
  json doc = {{"$schema", "https://json.schemastore.org/sarif-2.1.0.json"},
              {"version", "2.1.0"},
              {"runs", json::array({sarif_run})}};
  return doc.dump(2) + "\n";
}

}  // namespace pd
