#include "report/baseline.h"

#include <cmath>

#include "report/fail_on.h"
#include "report/json_input.h"
#include "results/fingerprint.h"
#include "tolerances.h"

namespace pd {

const char* baseline_state_name(BaselineState s) {
  switch (s) {
    case BaselineState::kNew:
      return "new";
    case BaselineState::kUnchanged:
      return "unchanged";
    case BaselineState::kUpdated:
      return "updated";
    case BaselineState::kAbsent:
      return "absent";
    case BaselineState::kUnknown:
      return "unknown";
  }
  return "?";
}

namespace {

bool is_finding_name(const std::string& s) {
  return s == "false_positive" || s == "interference" || s == "clearance_violation";
}

}  // namespace

Baseline parse_baseline(const std::string& text, const std::string& path) {
  const nlohmann::json doc = parse_json_input(text, path);
  const JsonAt root{doc, path, "$"};
  root.object();
  if (!root.has("pairs") && root.has("summary"))
    root.fail("a JSON Lines summary is not a baseline: use a --format json report");
  const JsonAt pairs = root["pairs"];
  Baseline b;
  b.path = path;
  b.settings = prior_settings_of(doc);
  for (size_t k = 0; k < pairs.array().size(); ++k) {
    const JsonAt p = pairs[k];
    BaselineFinding f;
    f.a = p["a"].string();
    f.b = p["b"].string();
    f.status = p["status"].string();
    static const char* kStatuses[] = {"separated", "false_positive",      "interference",
                                      "error",     "clearance_violation", "undecided"};
    bool known = false;
    for (const char* s : kStatuses) known |= f.status == s;
    if (!known) p["status"].fail("unknown status \"" + f.status + "\"");
    if (!is_finding_name(f.status)) continue;
    f.depth = p["depth"].number();
    if (!std::isfinite(f.depth) || f.depth < 0) p["depth"].fail("must be a finite number >= 0");
    f.fingerprint = pair_fingerprint(f.a, f.b);
    if (p.has("fingerprint") && p["fingerprint"].string() != f.fingerprint)
      p["fingerprint"].fail("does not match the ids (the report was edited, or is not pdcheck's)");
    if (!b.findings.emplace(f.fingerprint, f).second)
      p.fail("the pair " + f.a + " / " + f.b + " appears twice");
  }
  return b;
}

Baseline load_baseline(const std::string& path) {
  return parse_baseline(read_input_file(path), path);
}

BaselineState compare_finding(const BaselineFinding* old, Status now, double depth,
                              double tolerance) {
  if (!old) return BaselineState::kNew;
  if (old->status != status_name(now)) return BaselineState::kUpdated;
  const double change = std::abs(depth - old->depth);
  const double material =
      std::max(tol::kBaselineDepthAbs * tolerance, tol::kBaselineDepthRel * old->depth);
  return change > material ? BaselineState::kUpdated : BaselineState::kUnchanged;
}

std::vector<GoneFinding> gone_findings(const Baseline& baseline, const RunResult& run,
                                       const std::optional<std::set<std::string>>& listed) {
  std::map<std::string, const Part*> parts;
  for (const Part& p : run.parts) parts[p.id] = &p;
  std::map<std::string, const PairResult*> pairs;
  for (const PairResult& r : run.pairs)
    pairs[pair_fingerprint(run.parts[r.a].id, run.parts[r.b].id)] = &r;

  std::vector<GoneFinding> gone;
  for (const auto& [fp, f] : baseline.findings) {
    const auto it = pairs.find(fp);
    GoneFinding g{f, BaselineState::kUnknown, ""};
    if (it != pairs.end()) {
      const PairResult& r = *it->second;
      if (is_finding(r.status)) continue;  // still a finding: compared, not gone
      if (r.status == Status::kSeparated) {
        g.state = BaselineState::kAbsent;
        g.reason = "checked: separated";
      } else {
        g.reason = r.status == Status::kUndecided ? "the pair is undecided: " + r.reason
                                                  : "the pair failed: " + r.error;
      }
      gone.push_back(g);
      continue;
    }
    for (const std::string* id : {&f.a, &f.b}) {
      if (!g.reason.empty()) break;
      const auto p = parts.find(*id);
      if (p == parts.end())
        g.reason = "part \"" + *id + "\" is not in the scene";
      else if (p->second->error)
        g.reason = "part \"" + *id + "\" failed to load: " + *p->second->error;
    }
    if (g.reason.empty() && listed && !listed->count(fp))
      g.reason = "the pair was not checked (not among the scene's pairs)";
    if (g.reason.empty()) {
      g.state = BaselineState::kAbsent;
      g.reason = "checked: culled by the broad phase (the boxes are apart)";
    }
    gone.push_back(g);
  }
  return gone;
}

}  // namespace pd
