// --csv FILE: one row per exported finding for spreadsheets (RFC 4180: a header
// row, CRLF line ends, a field quoted when it holds a comma, a quote, CR or LF,
// quotes doubled). Numbers as the JSON report writes them (the shortest text
// that reads back to the same double), rows in report order.
// docs/report-format.md, "CSV".
#include <nlohmann/json.hpp>

#include "report/export_finding.h"
#include "report/writer.h"

namespace pd {

namespace {

const char* const kColumns[] = {
    "a",     "b",    "fingerprint", "status", "depth", "depth_source",   "tolerance",   "margin",
    "units", "at_x", "at_y",        "at_z",   "group", "baseline_state", "suppression", "message"};

std::string field(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (const char c : s) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + "\"";
}

/// The JSON report's text of a number (nlohmann's shortest round trip).
std::string number(double x) {
  return nlohmann::json(x).dump();
}

std::string number(const std::optional<double>& x) {
  return x ? number(*x) : "";
}

void add_row(std::string& out, const std::vector<std::string>& cells) {
  for (size_t k = 0; k < cells.size(); ++k) {
    if (k) out += ',';
    out += field(cells[k]);
  }
  out += "\r\n";
}

}  // namespace

std::string render_csv(const ReportInput& in) {
  std::string out;
  add_row(out, std::vector<std::string>(std::begin(kColumns), std::end(kColumns)));
  for (size_t k = 0; k < in.run.pairs.size(); ++k) {
    if (!exported(in.run.pairs[k].status)) continue;
    const ExportFinding f = export_finding(in, k);
    const auto at = [&](int d) { return f.at ? number((*f.at)[d]) : std::string(); };
    add_row(out, {f.a, f.b, f.fingerprint, status_name(f.pair->status), number(f.depth),
                  f.depth ? f.pair->depth_source : std::string(), number(f.tolerance),
                  number(f.margin), in.context.units, at(0), at(1), at(2), f.group,
                  f.baseline_state, f.suppression, f.message});
  }
  return out;
}

}  // namespace pd
