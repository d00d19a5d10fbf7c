#include "report/review.h"

#include <algorithm>
#include <cstdio>

#include "batch/empty_input.h"
#include "results/fingerprint.h"

namespace pd {

bool contact_violation(const PairResult& r) {
  return r.status == Status::kClearanceViolation &&
         (!r.distance || *r.distance == 0 || (r.gap_band && *r.distance <= *r.gap_band));
}

PairReview review_pair(const PairResult& r, const std::vector<Part>& parts,
                       const ReviewOptions& options, FailOn bar) {
  PairReview pr;
  pr.fingerprint = pair_fingerprint(parts[r.a].id, parts[r.b].id);
  if (!is_finding(r.status)) return pr;
  if (options.baseline) {
    const auto it = options.baseline->findings.find(pr.fingerprint);
    pr.baseline_state =
        compare_finding(it == options.baseline->findings.end() ? nullptr : &it->second, r.status,
                        r.depth, r.tolerance.value_or(options.tolerance));
  }
  if (options.suppressions) {
    const auto it = options.suppressions->by_fingerprint.find(pr.fingerprint);
    if (it != options.suppressions->by_fingerprint.end()) {
      const Suppression& s = options.suppressions->entries[it->second];
      const Hold h = check_suppression(s, r.depth, options.today);
      if (h == Hold::kHolds)
        pr.suppressed = &s;
      else
        pr.not_holding = h;
    }
  }
  // An expected contact: an overlap up to the rule's max_depth, and the
  // clearance violation a contact is (docs/scene-format.md).
  if (!pr.suppressed && options.expected && !r.expected.empty() &&
      (r.status == Status::kInterference || contact_violation(r))) {
    const auto it = options.expected->by_name.find(r.expected);
    if (it != options.expected->by_name.end()) {
      const Suppression& s = options.expected->entries[it->second];
      if (check_suppression(s, r.depth, options.today) == Hold::kHolds)
        pr.suppressed = &s;
      else
        pr.expected_exceeded = true;
    }
  }
  bool fails = reaches_bar(bar, r.status) && !pr.suppressed;
  if (bar == FailOn::kNew)
    fails = fails && pr.baseline_state &&
            (*pr.baseline_state == BaselineState::kNew ||
             *pr.baseline_state == BaselineState::kUpdated);
  pr.fails = fails;
  return pr;
}

FailOn effective_fail_on(const RunResult& run, const ReviewOptions& options) {
  if (options.fail_on) return *options.fail_on;
  return default_fail_on(std::count(run.simulated.begin(), run.simulated.end(), "clearance") > 0);
}

namespace {

std::string depth_text(double d) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", d);
  return buf;
}

}  // namespace

Review review_run(const RunResult& run, const ReviewOptions& options, bool incomplete) {
  Review rv;
  rv.fail_on = effective_fail_on(run, options);
  rv.baseline_used = options.baseline != nullptr;
  rv.suppressions_used = options.suppressions != nullptr;
  std::set<std::string> failed;  // fingerprints of pairs that could not be solved
  for (const PairResult& r : run.pairs) {
    PairReview pr = review_pair(r, run.parts, options, rv.fail_on);
    if (pr.baseline_state) ++rv.state_count[static_cast<int>(*pr.baseline_state)];
    rv.suppressed += pr.suppressed ? 1 : 0;
    if (pr.suppressed && !pr.suppressed->rule.empty()) ++rv.expected_counts[r.expected].first;
    if (pr.expected_exceeded) ++rv.expected_counts[r.expected].second;
    rv.failing += pr.fails ? 1 : 0;
    if (not_decided(r.status)) failed.insert(pr.fingerprint);
    if (pr.not_holding) {
      const Suppression& s =
          options.suppressions->entries[options.suppressions->by_fingerprint.at(pr.fingerprint)];
      SuppressionIssue issue{&s, "", "", false};
      if (*pr.not_holding == Hold::kExpired) {
        issue.kind = "expired";
        issue.detail = "expired on " + s.expires + "; the finding is reported as if unsuppressed";
        issue.fails = !options.allow_stale;
      } else {
        issue.kind = "exceeded";
        issue.detail = "depth " + depth_text(r.depth) + " " + options.units +
                       " exceeds max_depth " + depth_text(*s.max_depth) + " " + options.units +
                       "; the finding is reported as if unsuppressed";
      }
      rv.suppression_issues.push_back(issue);
    }
    rv.pairs.push_back(std::move(pr));
  }
  std::vector<std::string> ids;
  for (const Part& p : run.parts) ids.push_back(p.id);
  rv.groups = group_findings(run.pairs, ids);
  for (size_t k = 0; k < run.pairs.size(); ++k)
    if (rv.groups.group_of[k] >= 0) rv.pairs[k].group = rv.groups.groups[rv.groups.group_of[k]].id;
  if (options.baseline) {
    rv.gone = gone_findings(*options.baseline, run, options.listed);
    for (const GoneFinding& g : rv.gone) ++rv.state_count[static_cast<int>(g.state)];
  }
  if (options.suppressions) {
    std::set<std::string> matched;
    for (const PairReview& pr : rv.pairs)
      if (pr.suppressed || pr.not_holding) matched.insert(pr.fingerprint);
    std::set<std::string> loaded;
    for (const Part& p : run.parts)
      if (!p.error) loaded.insert(p.id);
    for (const Suppression& s : options.suppressions->entries) {
      if (matched.count(s.fingerprint)) continue;
      // An entry whose pair could not be checked is not stale: nobody knows.
      const bool unchecked = failed.count(s.fingerprint) || !loaded.count(s.a) ||
                             !loaded.count(s.b) ||
                             (options.listed && !options.listed->count(s.fingerprint));
      if (unchecked) {
        rv.suppression_issues.push_back(
            {&s, "unchecked", "the pair was not checked in this run: the entry is kept", false});
      } else {
        const bool expired = !s.expires.empty() && options.today > s.expires;
        rv.suppression_issues.push_back(
            {&s, expired ? "expired" : "unmatched",
             std::string(expired ? "expired on " + s.expires + " and m" : "m") +
                 "atched no finding: the pair is clean now; remove the entry",
             !options.allow_stale});
      }
    }
  }
  const bool stale = std::any_of(rv.suppression_issues.begin(), rv.suppression_issues.end(),
                                 [](const SuppressionIssue& i) { return i.fails; });
  rv.exit_code = run_exit_code(incomplete, rv.failing > 0 || stale);
  if (!options.allow_empty && every_part_failed(run)) rv.exit_code = kExitBadInput;
  rv.own_exit_code = rv.exit_code;
  if (options.deferred) rv.exit_code = kExitClean, rv.deferred = true;
  return rv;
}

}  // namespace pd
