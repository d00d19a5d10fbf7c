#include "report/writer.h"

namespace pd {

const std::vector<ReportFormat>& report_formats() {
  static const std::vector<ReportFormat> formats = {
      {"json", "one JSON document (docs/report-format.md)", render_json},
      {"jsonl", "a JSON line per pair, then a summary line", render_jsonl},
      {"junit", "JUnit XML: a test case per candidate pair (docs/ci.md)", render_junit},
      {"sarif", "SARIF 2.1.0: a result per finding (docs/ci.md)", render_sarif},
      {"table", "the verdict and a short table of the findings, for people", render_table},
  };
  return formats;
}

const ReportFormat* find_report_format(const std::string& name) {
  for (const ReportFormat& f : report_formats())
    if (name == f.name) return &f;
  return nullptr;
}

}  // namespace pd
