#include "report/extra_outputs.h"

#include "report/review_text.h"
#include "report/write_html.h"

namespace pd {

ExtraOutputs check_extra_outputs(const ExtraOutputPaths& paths) {
  ExtraOutputs out;
  if (paths.junit) out.junit = check_output_file("--junit", *paths.junit);
  if (paths.sarif) out.sarif = check_output_file("--sarif", *paths.sarif);
  if (paths.html) out.html = check_output_file("--html", *paths.html);
  if (out.html) check_html_assets();
  if (paths.write_suppressions)
    out.write_suppressions = check_output_file("--write-suppressions", *paths.write_suppressions);
  if (paths.csv) out.csv = check_output_file("--csv", *paths.csv);
  if (paths.bcf) out.bcf = check_output_file("--bcf", *paths.bcf);
  return out;
}

void write_extra_outputs(const ExtraOutputs& out, const ReportInput& report,
                         const std::function<std::string()>& html_page) {
  if (out.junit) write_output_file(*out.junit, render_junit(report));
  if (out.sarif) write_output_file(*out.sarif, render_sarif(report));
  if (out.html) write_output_file(*out.html, html_page());
  if (out.write_suppressions)
    write_output_file(*out.write_suppressions,
                      suppressions_to_write(report, report.review_options.today));
  if (out.csv) write_output_file(*out.csv, render_csv(report));
  if (out.bcf) write_output_file(*out.bcf, render_bcf(report));
}

}  // namespace pd
