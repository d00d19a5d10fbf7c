#include "report/rules_report.h"

namespace pd {

using json = nlohmann::ordered_json;

namespace {

// "a" and, unless a self pair, "b": the set names.
void set_pair(json& j, const Rules& r, const SetPair& p) {
  j["a"] = r.sets[p.a].name;
  if (!p.self()) j["b"] = r.sets[p.b].name;
}

}  // namespace

json rules_json(const RuleCoverage& c) {
  const Rules& r = *c.rules;
  json sets = json::array(), tests = json::array(), ignore = json::array(),
       expected = json::array(), pairs = json::array();
  for (size_t k = 0; k < r.sets.size(); ++k)
    sets.push_back(
        {{"name", r.sets[k].name}, {"optional", r.sets[k].optional}, {"parts", c.set_parts[k]}});
  for (size_t k = 0; k < r.tests.size(); ++k) {
    json t = {{"name", r.tests[k].name}};
    set_pair(t, r, r.tests[k].sets);
    if (r.tests[k].tolerance) t["tolerance"] = *r.tests[k].tolerance;
    if (r.tests[k].clearance) t["clearance"] = *r.tests[k].clearance;
    t["pairs"] = c.test_pairs[k];
    tests.push_back(t);
  }
  for (size_t k = 0; k < r.ignore.size(); ++k) {
    const IgnoreRule& g = r.ignore[k];
    json j = {{"name", g.name}};
    if (g.same == IgnoreRule::Same::kGroup)
      j["same"] = "group";
    else if (g.same == IgnoreRule::Same::kFile)
      j["same"] = "file";
    else
      set_pair(j, r, g.sets);
    j["reason"] = g.reason;
    j["pairs"] = c.ignore_pairs[k];
    ignore.push_back(j);
  }
  for (size_t k = 0; k < r.expected.size(); ++k) {
    const ExpectedRule& e = r.expected[k];
    json j = {{"name", e.name}};
    set_pair(j, r, e.sets);
    j["max_depth"] = e.max_depth;
    j["reason"] = e.reason;
    j["where"] = e.where;
    j["pairs"] = c.expected_pairs[k];
    expected.push_back(j);
  }
  for (const PairRule& p : r.pairs) {
    json j = {{"pair", {p.a, p.b}}};
    if (p.tolerance) j["tolerance"] = *p.tolerance;
    if (p.clearance) j["clearance"] = *p.clearance;
    pairs.push_back(j);
  }
  return {{"source", r.source},
          {"sets", sets},
          {"tests", tests},
          {"ignore", ignore},
          {"expected", expected},
          {"pairs", pairs},
          {"out_of_scope", c.out_of_scope},
          {"ignored", c.ignored}};
}

json merge_rules_sections(const std::vector<const json*>& sections) {
  json out = *sections.front();
  auto sum = [&](const char* list, size_t k) {
    long n = 0;
    for (const json* s : sections) n += (*s)[list][k]["pairs"].get<long>();
    out[list][k]["pairs"] = n;
  };
  for (const char* list : {"tests", "ignore", "expected"})
    for (size_t k = 0; k < out[list].size(); ++k) sum(list, k);
  for (const char* count : {"out_of_scope", "ignored"}) {
    long n = 0;
    for (const json* s : sections) n += (*s)[count].get<long>();
    out[count] = n;
  }
  return out;
}

}  // namespace pd
