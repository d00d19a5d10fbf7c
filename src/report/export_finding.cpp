#include "report/export_finding.h"

#include "report/finding_text.h"

namespace pd {

namespace {

/// The finding's group id, as the review found it (report/finding_groups.h).
std::string group_of(const ReportInput& in, size_t k) {
  return in.review.pairs[k].group;
}

/// Where the finding is: the pair's `at` when its depth method gives one.
std::optional<Vec3> at_of(const ReportInput& in, size_t k) {
  return in.run.pairs[k].at;
}

}  // namespace

bool exported(Status s) {
  return s != Status::kSeparated;
}

ExportFinding export_finding(const ReportInput& in, size_t k) {
  const PairResult& r = in.run.pairs[k];
  const PairReview& pr = in.review.pairs[k];
  ExportFinding f;
  f.index = k;
  f.pair = &r;
  f.review = &pr;
  f.a = in.run.parts[r.a].id;
  f.b = in.run.parts[r.b].id;
  f.fingerprint = pr.fingerprint;
  if (r.status != Status::kError) {
    f.depth = r.depth;
    f.margin = r.margin;
  }
  if (r.tolerance)
    f.tolerance = *r.tolerance;
  else if (!in.context.auto_tolerance)
    f.tolerance = in.context.tolerance;
  f.at = at_of(in, k);
  f.group = group_of(in, k);
  if (pr.baseline_state) f.baseline_state = baseline_state_name(*pr.baseline_state);
  if (pr.suppressed) f.suppression = pr.suppressed->reason;
  f.message = finding_text(r, in.run.parts, pr, in.context.units, in.context.tolerance);
  return f;
}

}  // namespace pd
