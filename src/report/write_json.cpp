// --format json: the report of docs/report-format.md with the run's review.
#include "report/groups_json.h"
#include "report/review_json.h"
#include "report/writer.h"

namespace pd {

nlohmann::ordered_json report_document(const ReportInput& in) {
  nlohmann::ordered_json doc = report_json(in.context, in.run);
  auto& pairs = doc["pairs"];
  for (size_t k = 0; k < pairs.size(); ++k) add_pair_review(pairs[k], in.review.pairs[k]);
  doc["groups"] = groups_json(in.review.groups, in.run);
  add_run_review(doc, doc["summary"], in.review, in.review_options);
  return doc;
}

std::string render_json(const ReportInput& in) {
  return report_document(in).dump(2) + "\n";
}

}  // namespace pd
