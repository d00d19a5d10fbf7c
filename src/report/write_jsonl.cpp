// --format jsonl: a line per pair in report order, then a summary line (the
// streamed form on stdout is written by the CLI as pairs finish).
#include "report/groups_json.h"
#include "report/review_json.h"
#include "report/writer.h"

namespace pd {

std::string render_jsonl(const ReportInput& in) {
  std::string text;
  for (size_t k = 0; k < in.run.pairs.size(); ++k) {
    nlohmann::ordered_json j = pair_json(in.run.pairs[k], in.run.parts);
    add_pair_review(j, in.review.pairs[k]);
    text += j.dump() + "\n";
  }
  text += jsonl_tail(in) + "\n";
  return text;
}

std::string jsonl_tail(const ReportInput& in) {
  // `part_errors` always, empty too: a reader need not test for the key.
  nlohmann::ordered_json tail = {{"summary", summary_json(summarize(in.run))},
                                 {"part_errors", nlohmann::ordered_json::array()}};
  for (const auto& p : in.run.parts)
    if (p.error) tail["part_errors"].push_back({{"id", p.id}, {"error", *p.error}});
  tail["groups"] = groups_json(in.review.groups, in.run);
  add_run_review(tail, tail["summary"], in.review, in.review_options);
  return tail.dump();
}

}  // namespace pd
