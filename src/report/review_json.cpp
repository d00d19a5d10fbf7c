#include "report/review_json.h"

namespace pd {

using json = nlohmann::ordered_json;

namespace {

json suppression_json(const Suppression& s) {
  json j = {{"reason", s.reason}};
  if (!s.rule.empty()) j["rule"] = s.rule;
  if (!s.owner.empty()) j["owner"] = s.owner;
  if (!s.expires.empty()) j["expires"] = s.expires;
  if (s.max_depth) j["max_depth"] = *s.max_depth;
  return j;
}

}  // namespace

void add_pair_review(json& pair, const PairReview& review) {
  if (review.baseline_state) pair["baseline_state"] = baseline_state_name(*review.baseline_state);
  if (review.suppressed) pair["suppressed"] = suppression_json(*review.suppressed);
  // Set, or cleared: a merged shard pair carries its shard's group.
  if (!review.group.empty())
    pair["group"] = review.group;
  else
    pair.erase("group");
}

void add_run_review(json& doc, json& summary, const Review& review, const ReviewOptions& options) {
  summary["fail_on"] = fail_on_name(review.fail_on);
  summary["failing"] = review.failing;
  if (review.suppressions_used || options.expected) summary["suppressed"] = review.suppressed;
  if (review.baseline_used) {
    json states;
    for (BaselineState s : kBaselineStates)
      states[baseline_state_name(s)] = review.state_count[static_cast<int>(s)];
    summary["baseline"] = states;
  }
  summary["exit_code"] = review.exit_code;
  if (review.deferred) summary["verdict"] = "deferred to pdcheck merge";
  if (review.baseline_used) {
    json gone = json::array();
    for (const GoneFinding& g : review.gone)
      gone.push_back({{"a", g.was.a},
                      {"b", g.was.b},
                      {"fingerprint", g.was.fingerprint},
                      {"baseline_state", baseline_state_name(g.state)},
                      {"status_was", g.was.status},
                      {"depth_was", g.was.depth},
                      {"reason", g.reason}});
    doc["baseline"] = {{"file", options.baseline->path}, {"gone", gone}};
  }
  if (options.expected && doc.contains("rules") && doc["rules"].contains("expected"))
    for (json& e : doc["rules"]["expected"]) {  // the review's share of the rules' coverage
      const auto it = review.expected_counts.find(e["name"].get<std::string>());
      const bool found = it != review.expected_counts.end();
      e["suppressed"] = found ? it->second.first : 0;
      e["exceeded"] = found ? it->second.second : 0;
    }
  if (review.suppressions_used) {
    json issues = json::array();
    for (const SuppressionIssue& i : review.suppression_issues)
      issues.push_back({{"a", i.entry->a},
                        {"b", i.entry->b},
                        {"entry", i.entry->where},
                        {"issue", i.kind},
                        {"detail", i.detail},
                        {"fails", i.fails}});
    doc["suppressions"] = {{"file", options.suppressions->path}, {"issues", issues}};
  }
}

}  // namespace pd
