#include "report/suppressions.h"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <nlohmann/json.hpp>

#include "report/json_input.h"
#include "results/fingerprint.h"

namespace pd {

bool is_iso_date(const std::string& s) {
  int y = 0, m = 0, d = 0;
  char tail = 0;
  if (s.size() != 10 || s[4] != '-' || s[7] != '-' ||
      std::sscanf(s.c_str(), "%4d-%2d-%2d%c", &y, &m, &d, &tail) != 3)
    return false;
  for (size_t k : {0, 1, 2, 3, 5, 6, 8, 9})
    if (s[k] < '0' || s[k] > '9') return false;
  if (m < 1 || m > 12 || d < 1) return false;
  static const int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
  return d <= kDays[m - 1] + (m == 2 && leap ? 1 : 0);
}

std::string utc_today() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[16];
  std::strftime(buf, sizeof buf, "%Y-%m-%d", &tm);
  return buf;
}

Suppressions parse_suppressions(const std::string& text, const std::string& path) {
  const nlohmann::json doc = parse_json_input(text, path);
  const JsonAt root{doc, path, "$"};
  root.only_keys({"$schema", "version", "suppressions"});
  if (root.has("version") && root["version"].value != 1) root["version"].fail("must be 1");
  const JsonAt list = root["suppressions"];
  Suppressions out;
  out.path = path;
  for (size_t k = 0; k < list.array().size(); ++k) {
    const JsonAt e = list[k];
    e.only_keys({"a", "b", "reason", "owner", "expires", "max_depth", "comment"});
    Suppression s;
    s.where = e.where;
    s.a = e["a"].string();
    s.b = e["b"].string();
    if (s.a.empty()) e["a"].fail("must be a part id");
    if (s.b.empty()) e["b"].fail("must be a part id");
    if (s.a == s.b) e["b"].fail("a part cannot be paired with itself");
    s.reason = e["reason"].string();
    if (s.reason.find_first_not_of(" \t\r\n") == std::string::npos)
      e["reason"].fail("must say why the finding is accepted (a non-empty string)");
    if (e.has("owner")) s.owner = e["owner"].string();
    if (e.has("comment")) s.comment = e["comment"].string();
    if (e.has("expires")) {
      s.expires = e["expires"].string();
      if (!is_iso_date(s.expires)) e["expires"].fail("must be a date YYYY-MM-DD");
    }
    if (e.has("max_depth")) {
      const double d = e["max_depth"].number();
      if (!std::isfinite(d) || d < 0) e["max_depth"].fail("must be a finite number >= 0");
      s.max_depth = d;
    }
    s.fingerprint = pair_fingerprint(s.a, s.b);
    const auto [it, fresh] = out.by_fingerprint.emplace(s.fingerprint, out.entries.size());
    if (!fresh)
      e.fail("the pair " + s.a + " / " + s.b + " is already suppressed at " +
             out.entries[it->second].where);
    out.entries.push_back(s);
  }
  return out;
}

Suppressions load_suppressions(const std::string& path) {
  return parse_suppressions(read_input_file(path), path);
}

Hold check_suppression(const Suppression& s, double depth, const std::string& today) {
  if (!s.expires.empty() && today > s.expires) return Hold::kExpired;  // ISO dates sort
  if (s.max_depth && depth > *s.max_depth) return Hold::kExceeded;
  return Hold::kHolds;
}

std::string suppressions_file_text(const std::vector<FindingToSuppress>& findings,
                                   const std::string& units, const std::string& today) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& f : findings) {
    nlohmann::ordered_json e;
    if (f.keep) {
      const Suppression& s = *f.keep;
      e = {{"a", s.a}, {"b", s.b}, {"reason", s.reason}};
      if (!s.owner.empty()) e["owner"] = s.owner;
      if (!s.expires.empty()) e["expires"] = s.expires;
      if (s.max_depth) e["max_depth"] = *s.max_depth;
      if (!s.comment.empty()) e["comment"] = s.comment;
    } else {
      char depth[64];
      std::snprintf(depth, sizeof depth, "%.6g", f.depth);
      e = {{"a", f.a},
           {"b", f.b},
           {"reason", ""},
           {"comment", f.status + ", " + f.depth_name + " " + depth + " " + units + " on " + today +
                           ": say why it is accepted in \"reason\"; \"owner\", \"expires\" "
                           "(YYYY-MM-DD) and \"max_depth\" are optional"}};
    }
    list.push_back(e);
  }
  return nlohmann::ordered_json{{"version", 1}, {"suppressions", list}}.dump(2) + "\n";
}

}  // namespace pd
