#include "ci_options.h"

#include "report/fail_on.h"

void add_ci_options(CLI::App& app, CiOptions& o) {
  std::vector<std::string> bars;
  std::string bar_help = "which findings make the exit code 1:";
  for (const auto& f : pd::kFailOnNames) {
    bars.push_back(f.name);
    bar_help += std::string(" ") + f.name + " (" + f.meaning + ");";
  }
  bar_help += " default: interference, or clearance when the scene checks clearance";
  app.add_option("--fail-on", o.review.fail_on, bar_help)->check(CLI::IsMember(bars));
  app.add_option("--baseline", o.review.baseline,
                 "a previous JSON report: mark each finding new, unchanged or updated and list "
                 "the baseline's findings that are absent or unknown now (a report in another unit "
                 "is refused)");
  app.add_option("--suppressions", o.review.suppressions,
                 "reviewed suppressions (JSON, docs/ci.md): listed findings are reported as "
                 "suppressed and do not fail the run");
  app.add_flag("--allow-stale-suppressions", o.review.allow_stale,
               "a suppression that matched nothing or expired does not fail the run");
  app.add_option("--write-suppressions", o.write_suppressions,
                 "write a starting suppressions file for this run's findings (reasons to fill in)");
  app.add_option("--junit", o.junit, "also write JUnit XML to this file (atomically)");
  app.add_option("--sarif", o.sarif, "also write SARIF 2.1.0 to this file (atomically)");
  app.add_option("--html", o.html,
                 "also write a self-contained HTML page with a 3D view of every finding "
                 "(atomically; docs/report-format.md)");
  app.add_option("--csv", o.csv,
                 "also write CSV (RFC 4180): a row per pair that is not separated (atomically; "
                 "docs/report-format.md)");
  app.add_option("--bcf", o.bcf,
                 "also write BCF 3.0 (a zip): a topic per finding that needs a person, with a "
                 "viewpoint on it (atomically; docs/report-format.md)");
}

pd::ExtraOutputPaths extra_output_paths(const CLI::App& app, const CiOptions& o) {
  pd::ExtraOutputPaths p;
  if (app.count("--junit")) p.junit = o.junit;
  if (app.count("--sarif")) p.sarif = o.sarif;
  if (app.count("--html")) p.html = o.html;
  if (app.count("--write-suppressions")) p.write_suppressions = o.write_suppressions;
  if (app.count("--csv")) p.csv = o.csv;
  if (app.count("--bcf")) p.bcf = o.bcf;
  return p;
}
