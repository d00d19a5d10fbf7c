#include "report/expected_rules.h"

#include "report/input_error.h"

namespace pd {

namespace {

void add(ExpectedRules& out, Suppression s) {
  out.by_name.emplace(s.rule, out.entries.size());
  out.entries.push_back(std::move(s));
}

}  // namespace

ExpectedRules expected_rules_of(const Rules& rules) {
  ExpectedRules out;
  for (const ExpectedRule& e : rules.expected) {
    Suppression s;
    s.rule = e.name;
    s.reason = e.reason;
    s.max_depth = e.max_depth;
    s.where = e.where;
    add(out, std::move(s));
  }
  return out;
}

ExpectedRules expected_rules_of_report(const nlohmann::ordered_json& rules_section,
                                       const std::string& path) {
  ExpectedRules out;
  if (!rules_section.is_object() || !rules_section.contains("expected")) return out;
  try {
    for (const auto& e : rules_section.at("expected")) {
      Suppression s;
      s.rule = e.at("name").get<std::string>();
      s.reason = e.at("reason").get<std::string>();
      s.max_depth = e.at("max_depth").get<double>();
      s.where = e.value("where", "");
      add(out, std::move(s));
    }
  } catch (const nlohmann::json::exception& ex) {
    throw ReportInputError(path + ": $.rules.expected: " + ex.what());
  }
  return out;
}

std::string suppression_origin(const Suppression& s, const std::string& suppressions_path) {
  if (!s.rule.empty()) return "expected-contact rule \"" + s.rule + "\", " + s.where;
  return suppressions_path + " " + s.where;
}

}  // namespace pd
