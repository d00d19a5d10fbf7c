#include "report/verdict.h"

namespace pd {

namespace {

long count(const nlohmann::ordered_json& s, const char* key) {
  const auto it = s.find(key);
  return it != s.end() && it->is_number_integer() ? it->get<long>() : 0;
}

// "1 interference", "3 false positives", "0 errors".
std::string counted(long n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

void append(std::string& list, const std::string& item) {
  list += (list.empty() ? "" : ", ") + item;
}

}  // namespace

Verdict run_verdict(const nlohmann::ordered_json& s) {
  const long interference = count(s, "interference"), clearance = count(s, "clearance_violation"),
             false_positive = count(s, "false_positive"), separated = count(s, "separated"),
             error = count(s, "error"), undecided = count(s, "undecided"),
             unchecked = count(s, "unchecked"), part_errors = count(s, "part_errors"),
             candidates = count(s, "candidate_pairs");
  const bool incomplete = error || undecided || unchecked || part_errors;
  long code = incomplete ? 3 : interference ? 1 : 0;
  if (s.contains("exit_code") && s["exit_code"].is_number_integer())
    code = s["exit_code"].get<long>();

  Verdict v;
  append(v.counts, counted(interference, "interference", "interferences"));
  if (s.contains("clearance_violation"))
    append(v.counts, counted(clearance, "clearance violation", "clearance violations"));
  append(v.counts, counted(false_positive, "false positive", "false positives"));
  append(v.counts, std::to_string(separated) + " separated of " +
                       counted(candidates, "candidate pair", "candidate pairs"));
  if (undecided) append(v.counts, std::to_string(undecided) + " undecided");
  if (error) append(v.counts, counted(error, "pair error", "pair errors"));
  if (unchecked) append(v.counts, std::to_string(unchecked) + " unchecked");
  if (part_errors) append(v.counts, counted(part_errors, "unusable part", "unusable parts"));

  const std::string exit = " (exit code " + std::to_string(code) + ")";
  const std::string bar =
      s.contains("fail_on") && s["fail_on"].is_string() ? s["fail_on"].get<std::string>() : "";
  if (code == 0) {
    v.state = "pass";
    v.headline = interference == 0 && clearance == 0
                     ? "PASS: no interference"
                     : "PASS: no finding fails the run" +
                           (bar.empty() ? std::string() : " (fail_on " + bar + ")");
  } else if (code == 1) {
    v.state = "fail";
    const bool reviewed = s.contains("failing");
    const long failing = reviewed ? count(s, "failing") : interference;
    if (reviewed && failing == 0)
      v.headline = "FAIL: a suppression needs attention";
    else if (bar.empty() || bar == "interference")
      v.headline = "FAIL: " + counted(failing, "interference", "interferences");
    else
      v.headline = "FAIL: " + counted(failing, "failing finding", "failing findings") +
                   " (fail_on " + bar + ")";
  } else if (code == 3) {
    v.state = "incomplete";
    std::string why;
    if (undecided) append(why, std::to_string(undecided) + " undecided");
    if (error) append(why, counted(error, "pair failed", "pairs failed"));
    if (unchecked) append(why, std::to_string(unchecked) + " unchecked");
    if (part_errors) append(why, counted(part_errors, "part unusable", "parts unusable"));
    v.headline = "INCOMPLETE: not every pair was checked" + (why.empty() ? "" : " (" + why + ")") +
                 "; not a pass";
    if (interference) v.headline += ", " + counted(interference, "interference", "interferences");
  } else {
    v.state = "incomplete";
    v.headline = "NOTHING CHECKED";
  }
  v.headline += exit;
  return v;
}

}  // namespace pd
