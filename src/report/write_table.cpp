// --format table, and stdout on a terminal without -o: the verdict and a short
// table of the findings for people, from the JSON report's own fields (so it
// says what the report says). docs/report-format.md, "Table".
#include <algorithm>
#include <array>
#include <nlohmann/json.hpp>

#include "printable.h"
#include "report/finding_text.h"
#include "report/verdict.h"
#include "report/writer.h"

namespace pd {

namespace {

using json = nlohmann::ordered_json;

constexpr size_t kTableRows = 20;

int status_rank(const std::string& s) {
  static const char* const order[] = {"interference", "clearance_violation", "undecided", "error",
                                      "false_positive"};
  for (int k = 0; k < 5; ++k)
    if (s == order[k]) return k;
  return 5;
}

double number_at(const json& p, const char* key) {
  return p.contains(key) && p[key].is_number() ? p[key].get<double>() : 0.0;
}

// What the depth column holds for one finding.
std::string depth_cell(const json& p) {
  const std::string status = p.value("status", "");
  if (status == "error") return "-";
  if (status == "undecided" && p.contains("depth_bounds") && p["depth_bounds"].size() == 2)
    return short_number(p["depth_bounds"][0].get<double>()) + " to " +
           short_number(p["depth_bounds"][1].get<double>());
  if (status == "clearance_violation" && p.contains("distance"))
    return "gap " + short_number(number_at(p, "distance"));
  return short_number(number_at(p, "depth"));
}

// What follows the parts: why, for what is not a plain number.
std::string note_cell(const json& p) {
  std::string note;
  auto add = [&note](const std::string& s) { note += (note.empty() ? "" : "; ") + s; };
  if (p.contains("error")) add(p["error"].get<std::string>());
  if (p.contains("reason")) add(p["reason"].get<std::string>());
  if (p.contains("baseline_state")) add(p["baseline_state"].get<std::string>());
  if (p.contains("suppressed")) add("suppressed");
  return note;
}

std::string padded(const std::string& s, size_t width) {
  return s + std::string(width > s.size() ? width - s.size() : 0, ' ');
}

}  // namespace

std::string render_table(const ReportInput& in) {
  const json doc = report_document(in);
  const Verdict verdict = run_verdict(doc["summary"]);
  const std::string units = doc.value("units", "");
  std::string out = "pdcheck: " + printable(doc.value("scene", "")) + ": " + verdict.headline +
                    "\n" + verdict.counts + "\n";

  std::vector<const json*> findings;
  for (const json& p : doc["pairs"])
    if (p.value("status", "") != "separated") findings.push_back(&p);
  std::stable_sort(findings.begin(), findings.end(), [](const json* x, const json* y) {
    const int rx = status_rank(x->value("status", "")), ry = status_rank(y->value("status", ""));
    return rx != ry ? rx < ry : number_at(*x, "depth") > number_at(*y, "depth");
  });
  if (findings.empty()) return out + "No findings: every candidate pair is separated.\n";

  std::vector<std::array<std::string, 4>> rows = {{"status", "depth (" + units + ")", "parts", ""}};
  for (size_t k = 0; k < findings.size() && k < kTableRows; ++k) {
    const json& p = *findings[k];
    rows.push_back({p.value("status", ""), depth_cell(p),
                    printable(p.value("a", "")) + " / " + printable(p.value("b", "")),
                    printable(note_cell(p))});
  }
  size_t w0 = 0, w1 = 0;
  for (const auto& r : rows) {
    w0 = std::max(w0, r[0].size());
    w1 = std::max(w1, r[1].size());
  }
  out += "\n";
  for (const auto& r : rows)
    out += padded(r[0], w0 + 2) + padded(r[1], w1 + 2) + r[2] + (r[3].empty() ? "" : ": " + r[3]) +
           "\n";
  if (findings.size() > kTableRows)
    out += "... and " + std::to_string(findings.size() - kTableRows) + " more findings\n";
  return out +
         "\nSeparated pairs are not listed. Every pair and field: the JSON report (--format json, "
         "-o FILE, or a pipe).\n";
}

}  // namespace pd
