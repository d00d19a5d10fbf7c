// --junit FILE: JUnit XML for CI test views (GitLab, Jenkins). One suite per
// scene, one test case per candidate pair named by its fingerprint; a failure
// for each finding at or above --fail-on, skipped for a suppressed finding, an
// error for a pair or part that could not be checked. docs/ci.md.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "report/finding_text.h"
#include "report/markup_escape.h"
#include "report/writer.h"

namespace pd {

namespace {

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", std::max(0.0, s));
  return buf;
}

/// The stable, unique test name: the ids in bytewise order and the fingerprint.
std::string case_name(const std::string& a, const std::string& b, const std::string& fp) {
  return std::min(a, b) + " ~ " + std::max(a, b) + " [" + fp + "]";
}

}  // namespace

std::string render_junit(const ReportInput& in) {
  const RunResult& run = in.run;
  const Review& rv = in.review;
  const std::string& units = in.context.units;
  const double tol = in.context.tolerance;
  const std::string suite = in.context.scene_path == "-" ? "stdin" : in.context.scene_path;
  // CI views split class names at dots into packages: the scene file's stem, dots replaced.
  std::string stem = std::filesystem::path(suite).stem().string();
  std::replace(stem.begin(), stem.end(), '.', '_');
  const std::string classname = "pdcheck." + (stem.empty() ? "scene" : stem);
  long failures = 0, errors = 0, skipped = 0, tests = 0;
  std::string cases;
  for (size_t k = 0; k < run.pairs.size(); ++k) {
    const PairResult& r = run.pairs[k];
    const PairReview& pr = rv.pairs[k];
    const std::string text = finding_text(r, run.parts, pr, units, tol);
    cases += "    <testcase classname=\"" + markup_escape(classname) + "\" name=\"" +
             markup_escape(case_name(run.parts[r.a].id, run.parts[r.b].id, pr.fingerprint)) +
             "\" time=\"" + seconds(r.time_ms / 1000.0) + "\"";
    ++tests;
    if (not_decided(r.status)) {
      ++errors;
      cases += ">\n      <error type=\"" + std::string(status_name(r.status)) + "\" message=\"" +
               markup_escape(text) + "\">" + markup_escape(text) + "</error>\n    </testcase>\n";
    } else if (pr.suppressed) {
      ++skipped;
      cases += ">\n      <skipped>" +
               markup_escape(
                   "suppressed (" +
                   suppression_origin(*pr.suppressed, in.review_options.suppressions
                                                          ? in.review_options.suppressions->path
                                                          : "") +
                   "): " + text) +
               "</skipped>\n    </testcase>\n";
    } else if (pr.fails) {
      ++failures;
      cases += ">\n      <failure type=\"" + std::string(status_name(r.status)) + "\" message=\"" +
               markup_escape(text) + "\">" + markup_escape(text) + "</failure>\n    </testcase>\n";
    } else {
      cases += "/>\n";
    }
  }
  for (const Part& p : run.parts) {
    if (!p.error) continue;
    ++tests;
    ++errors;
    const std::string text = "part " + p.id + " could not be used: " + *p.error;
    cases += "    <testcase classname=\"" + markup_escape(classname) + "\" name=\"" +
             markup_escape("part " + p.id) + "\">\n      <error type=\"part_error\" message=\"" +
             markup_escape(text) + "\">" + markup_escape(text) + "</error>\n    </testcase>\n";
  }
  for (const SuppressionIssue& i : rv.suppression_issues) {
    if (!i.fails) continue;
    ++tests;
    ++failures;
    const std::string text = in.review_options.suppressions->path + " " + i.entry->where + " (" +
                             i.entry->a + " / " + i.entry->b + "): " + i.kind + ": " + i.detail;
    cases +=
        "    <testcase classname=\"" + markup_escape(classname) + "\" name=\"" +
        markup_escape("suppression " + case_name(i.entry->a, i.entry->b, i.entry->fingerprint)) +
        "\">\n      <failure type=\"stale_suppression\" message=\"" + markup_escape(text) + "\">" +
        markup_escape(text) + "</failure>\n    </testcase>\n";
  }
  const std::string counts = " tests=\"" + std::to_string(tests) + "\" failures=\"" +
                             std::to_string(failures) + "\" errors=\"" + std::to_string(errors) +
                             "\"";
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<testsuites name=\"pdcheck\"" + counts + " time=\"" + seconds(run.seconds) + "\">\n";
  out += "  <testsuite name=\"" + markup_escape(suite) + "\"" + counts + " skipped=\"" +
         std::to_string(skipped) + "\" time=\"" + seconds(run.seconds) + "\">\n";
  out += "    <properties>\n";
  const std::pair<std::string, std::string> props[] = {{"tolerance", tolerance_words(in.context)},
                                                       {"fail_on", fail_on_name(rv.fail_on)},
                                                       {"exit_code", std::to_string(rv.exit_code)}};
  for (const auto& [name, value] : props)
    out += "      <property name=\"" + markup_escape(name) + "\" value=\"" + markup_escape(value) +
           "\"/>\n";
  out += "    </properties>\n" + cases + "  </testsuite>\n</testsuites>\n";
  return out;
}

}  // namespace pd
