// The report-writer seam: every output format is one render function in its
// own file (write_<format>.cpp) and one row of report_formats().
#pragma once

#include <string>
#include <vector>

#include "batch/run_result.h"
#include "report/report_json.h"
#include "report/review.h"

namespace pd {

/// Everything a writer may show: the run, how it was asked for, and its review.
struct ReportInput {
  const ReportContext& context;
  const RunResult& run;
  const Review& review;
  const ReviewOptions& review_options;
};

struct ReportFormat {
  const char* name;
  const char* description;
  std::string (*render)(const ReportInput&);
};

/// json, jsonl, junit, sarif, table: the table the CLI's --format and docs follow.
const std::vector<ReportFormat>& report_formats();
const ReportFormat* find_report_format(const std::string& name);

std::string render_json(const ReportInput& in);  // write_json.cpp
/// The JSON report as a document (render_json's, before printing; --html reads it).
nlohmann::ordered_json report_document(const ReportInput& in);  // write_json.cpp
std::string render_jsonl(const ReportInput& in);                // write_jsonl.cpp
/// The JSON Lines summary line, also after pair lines streamed as they finished.
std::string jsonl_tail(const ReportInput& in);    // write_jsonl.cpp
std::string render_junit(const ReportInput& in);  // write_junit.cpp
std::string render_sarif(const ReportInput& in);  // write_sarif.cpp
/// --format table (stdout on a terminal without -o): the verdict and the findings.
std::string render_table(const ReportInput& in);  // write_table.cpp
/// --csv: a row per pair that is not separated (RFC 4180).
std::string render_csv(const ReportInput& in);  // write_csv.cpp
/// --bcf: a BCF 3.0 zip, a topic per finding that needs a person (bcf_topics.h).
std::string render_bcf(const ReportInput& in);  // write_bcf.cpp

}  // namespace pd
