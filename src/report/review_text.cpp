#include "report/review_text.h"

#include "report/finding_text.h"
#include "report/group_text.h"

namespace pd {

std::string review_lines(const ReportInput& in) {
  const Review& rv = in.review;
  std::string out;
  long shown = 0;
  for (size_t k = 0; k < in.run.pairs.size(); ++k) {
    if (!rv.pairs[k].fails) continue;
    if (++shown > 20) continue;
    out += "pdcheck: fails --fail-on " + std::string(fail_on_name(rv.fail_on)) + ": " +
           finding_text(in.run.pairs[k], in.run.parts, rv.pairs[k], in.context.units,
                        in.context.tolerance) +
           "\n";
  }
  if (shown > 20)
    out += "pdcheck: … and " + std::to_string(shown - 20) + " more failing findings\n";
  out += group_lines(in);
  for (const SuppressionIssue& i : rv.suppression_issues)
    out += std::string("pdcheck: ") + (i.fails ? "error" : "warning") + ": " +
           in.review_options.suppressions->path + " " + i.entry->where + " (" + i.entry->a + " / " +
           i.entry->b + "): " + i.kind + ": " + i.detail + "\n";
  if (rv.suppressions_used)
    out += "pdcheck: suppressions " + in.review_options.suppressions->path + ": " +
           std::to_string(rv.suppressed) + " finding(s) suppressed (not failing the run)\n";
  for (const auto& [rule, counts] : rv.expected_counts)
    out += "pdcheck: expected-contact rule " + rule + ": " + std::to_string(counts.first) +
           " finding(s) suppressed (not failing the run), " + std::to_string(counts.second) +
           " deeper than its max_depth\n";
  if (rv.baseline_used) {
    out += "pdcheck: baseline " + in.review_options.baseline->path + ":";
    for (BaselineState s : kBaselineStates)
      out += " " + std::to_string(rv.state_count[static_cast<int>(s)]) + " " +
             baseline_state_name(s) + (s == BaselineState::kUnknown ? "" : ",");
    out += "\n";
  }
  return out;
}

std::string suppressions_to_write(const ReportInput& in, const std::string& today) {
  const FailOn bar = in.review.fail_on == FailOn::kNew || in.review.fail_on == FailOn::kNone
                         ? FailOn::kClearance
                         : in.review.fail_on;
  std::vector<FindingToSuppress> findings;
  for (size_t k = 0; k < in.run.pairs.size(); ++k) {
    const PairResult& r = in.run.pairs[k];
    if (!reaches_bar(bar, r.status)) continue;
    const Suppressions* current = in.review_options.suppressions;
    const Suppression* keep = nullptr;
    if (current) {
      const auto it = current->by_fingerprint.find(in.review.pairs[k].fingerprint);
      if (it != current->by_fingerprint.end()) keep = &current->entries[it->second];
    }
    findings.push_back({in.run.parts[r.a].id, in.run.parts[r.b].id, status_name(r.status), r.depth,
                        depth_meaning(r.depth_source), keep});
  }
  return suppressions_file_text(findings, in.context.units, today);
}

}  // namespace pd
