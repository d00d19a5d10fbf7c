// Reading rules (scene/rules.h): strict as the scene, every error with the file
// and the JSON path.
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

#include "scene/json_strict.h"
#include "scene/rules.h"
#include "scene/scene.h"
#include "scene/units.h"

namespace pd {

using nlohmann::json;

namespace {

struct At {
  const std::string& file;
  std::string path;
  [[noreturn]] void fail(const std::string& what) const {
    throw SceneError(file + ": " + (path.empty() ? "" : path + ": ") + what);
  }
  At key(const std::string& k) const { return {file, path.empty() ? k : path + "." + k}; }
  At index(size_t k) const { return {file, path + "[" + std::to_string(k) + "]"}; }
};

void only_keys(const At& at, const json& obj, const std::set<std::string>& allowed) {
  if (!obj.is_object()) at.fail(std::string("expected an object, got ") + obj.type_name());
  for (auto it = obj.begin(); it != obj.end(); ++it)
    if (!allowed.count(it.key())) {
      std::string list;
      for (const auto& k : allowed) list += (list.empty() ? "" : ", ") + k;
      at.key(it.key()).fail("unknown key (allowed: " + list + ")");
    }
}

std::string text(const At& at, const json& j) {
  if (!j.is_string()) at.fail(std::string("expected a string, got ") + j.type_name());
  return j.get<std::string>();
}

std::string nonempty_text(const At& at, const json& j) {
  const std::string s = text(at, j);
  if (s.find_first_not_of(" \t\r\n") == std::string::npos) at.fail("must not be empty");
  return s;
}

std::vector<std::string> strings(const At& at, const json& j) {
  if (!j.is_array()) at.fail(std::string("expected a list of strings, got ") + j.type_name());
  std::vector<std::string> out;
  for (size_t k = 0; k < j.size(); ++k) out.push_back(nonempty_text(at.index(k), j[k]));
  return out;
}

/// A length: a number in the scene's unit, or a string with a unit suffix
/// ("0.2 mm"), read as --tolerance reads one (scene/units.h).
double length(const At& at, const json& j, const std::string& units) {
  double v = 0.0;
  if (j.is_number()) {
    v = j.get<double>();
  } else if (j.is_string()) {
    const auto l = parse_length(j.get<std::string>());
    if (!l)
      at.fail("expected a length such as 0.2 or \"0.2 mm\" (units " + std::string(kUnitNames) +
              "), got \"" + j.get<std::string>() + "\"");
    v = length_in(*l, units);
  } else {
    at.fail(std::string("expected a length (a number or \"0.2 mm\"), got ") + j.type_name());
  }
  if (!std::isfinite(v)) at.fail("not a finite length");
  return v;
}

double positive_length(const At& at, const json& j, const std::string& units) {
  const double v = length(at, j, units);
  if (!(v > 0)) at.fail("must be > 0");
  return v;
}

RuleSet rule_set(const At& at, const std::string& name, const json& j) {
  only_keys(at, j, {"ids", "tags", "groups", "optional"});
  RuleSet s;
  s.name = name;
  s.where = at.file + ": " + at.path;
  if (j.contains("ids")) s.ids = strings(at.key("ids"), j["ids"]);
  if (j.contains("tags")) s.tags = strings(at.key("tags"), j["tags"]);
  if (j.contains("groups")) s.groups = strings(at.key("groups"), j["groups"]);
  if (j.contains("optional")) {
    if (!j["optional"].is_boolean()) at.key("optional").fail("expected true or false");
    s.optional = j["optional"].get<bool>();
  }
  if (s.ids.empty() && s.tags.empty() && s.groups.empty())
    at.fail("a set needs at least one of \"ids\", \"tags\", \"groups\" (non-empty)");
  return s;
}

/// "a" (required) and "b" (absent: within a) as set indices.
SetPair set_pair(const At& at, const json& j, const std::map<std::string, int>& sets) {
  auto one = [&](const char* key) {
    const At k = at.key(key);
    const std::string name = text(k, j[key]);
    const auto it = sets.find(name);
    if (it == sets.end()) {
      std::string known;
      for (const auto& [n, i] : sets) known += (known.empty() ? "" : ", ") + n;
      k.fail("unknown set \"" + name + "\" (sets: " + (known.empty() ? "none" : known) + ")");
    }
    return it->second;
  };
  if (!j.contains("a")) at.fail("missing \"a\" (a set name)");
  SetPair p;
  p.a = one("a");
  if (j.contains("b")) p.b = one("b");
  return p;
}

std::string name_or(const At& at, const json& j, const std::string& fallback,
                    std::set<std::string>& seen) {
  const std::string name = j.contains("name") ? nonempty_text(at.key("name"), j["name"]) : fallback;
  if (!seen.insert(name).second) at.key("name").fail("the name \"" + name + "\" is used twice");
  return name;
}

const json& list(const At& at, const json& j) {
  if (!j.is_array()) at.fail(std::string("expected a list, got ") + j.type_name());
  return j;
}

void tests(const At& at, const json& j, Rules& r, const std::map<std::string, int>& sets,
           std::set<std::string>& names) {
  for (size_t k = 0; k < list(at, j).size(); ++k) {
    const At e = at.index(k);
    only_keys(e, j[k], {"name", "a", "b", "tolerance", "clearance"});
    RuleTest t;
    if (!j[k].contains("name")) e.fail("missing \"name\"");
    t.name = name_or(e, j[k], "", names);
    t.where = e.file + ": " + e.path;
    t.sets = set_pair(e, j[k], sets);
    if (j[k].contains("tolerance"))
      t.tolerance = positive_length(e.key("tolerance"), j[k]["tolerance"], r.units);
    if (j[k].contains("clearance"))
      t.clearance = positive_length(e.key("clearance"), j[k]["clearance"], r.units);
    r.tests.push_back(t);
  }
}

void ignores(const At& at, const json& j, Rules& r, const std::map<std::string, int>& sets,
             std::set<std::string>& names) {
  for (size_t k = 0; k < list(at, j).size(); ++k) {
    const At e = at.index(k);
    only_keys(e, j[k], {"name", "same", "a", "b", "reason"});
    IgnoreRule g;
    g.name = name_or(e, j[k], "ignore[" + std::to_string(k) + "]", names);
    g.where = e.file + ": " + e.path;
    if (!j[k].contains("reason"))
      e.fail("missing \"reason\" (say why these pairs are not checked)");
    g.reason = nonempty_text(e.key("reason"), j[k]["reason"]);
    const bool same = j[k].contains("same");
    if (same == (j[k].contains("a") || j[k].contains("b")))
      e.fail("give either \"same\" or the sets \"a\" (and \"b\")");
    if (same) {
      const std::string v = text(e.key("same"), j[k]["same"]);
      if (v == "group")
        g.same = IgnoreRule::Same::kGroup;
      else if (v == "file")
        g.same = IgnoreRule::Same::kFile;
      else
        e.key("same").fail("expected \"group\" or \"file\", got \"" + v + "\"");
    } else {
      g.sets = set_pair(e, j[k], sets);
    }
    r.ignore.push_back(g);
  }
}

void expected(const At& at, const json& j, Rules& r, const std::map<std::string, int>& sets,
              std::set<std::string>& names) {
  for (size_t k = 0; k < list(at, j).size(); ++k) {
    const At e = at.index(k);
    only_keys(e, j[k], {"name", "a", "b", "max_depth", "reason"});
    ExpectedRule x;
    x.name = name_or(e, j[k], "expected[" + std::to_string(k) + "]", names);
    x.where = e.file + ": " + e.path;
    x.sets = set_pair(e, j[k], sets);
    if (!j[k].contains("max_depth")) e.fail("missing \"max_depth\"");
    x.max_depth = length(e.key("max_depth"), j[k]["max_depth"], r.units);
    if (!(x.max_depth >= 0)) e.key("max_depth").fail("must be >= 0");
    if (!j[k].contains("reason")) e.fail("missing \"reason\" (say why the contact is expected)");
    x.reason = nonempty_text(e.key("reason"), j[k]["reason"]);
    r.expected.push_back(x);
  }
}

void pair_rules(const At& at, const json& j, Rules& r) {
  for (size_t k = 0; k < list(at, j).size(); ++k) {
    const At e = at.index(k);
    only_keys(e, j[k], {"pair", "tolerance", "clearance"});
    PairRule p;
    p.where = e.file + ": " + e.path;
    const json& pj = j[k].contains("pair") ? j[k]["pair"] : json();
    if (!pj.is_array() || pj.size() != 2) e.key("pair").fail("expected [id, id]");
    p.a = nonempty_text(e.key("pair").index(0), pj[0]);
    p.b = nonempty_text(e.key("pair").index(1), pj[1]);
    if (p.a == p.b) e.key("pair").fail("a part paired with itself");
    if (j[k].contains("tolerance"))
      p.tolerance = positive_length(e.key("tolerance"), j[k]["tolerance"], r.units);
    if (j[k].contains("clearance"))
      p.clearance = positive_length(e.key("clearance"), j[k]["clearance"], r.units);
    if (!p.tolerance && !p.clearance) e.fail("give \"tolerance\" or \"clearance\"");
    r.pairs.push_back(p);
  }
}

}  // namespace

Rules parse_rules(const json& j, const std::string& file, const std::string& at_path,
                  const std::string& units) {
  const At at{file, at_path};
  only_keys(at, j, {"$schema", "sets", "tests", "ignore", "expected", "pairs"});
  Rules r;
  r.source = at_path.empty() ? file : file + ": " + at_path;
  r.units = units;
  std::map<std::string, int> sets;
  if (j.contains("sets")) {
    const At s = at.key("sets");
    if (!j["sets"].is_object()) s.fail("expected an object: set name -> selector");
    for (auto it = j["sets"].begin(); it != j["sets"].end(); ++it) {
      if (it.key().empty()) s.fail("a set name must not be empty");
      sets.emplace(it.key(), static_cast<int>(r.sets.size()));
      r.sets.push_back(rule_set(s.key(it.key()), it.key(), it.value()));
    }
  }
  std::set<std::string> test_names, ignore_names, expected_names;
  if (j.contains("tests")) tests(at.key("tests"), j["tests"], r, sets, test_names);
  if (j.contains("ignore")) ignores(at.key("ignore"), j["ignore"], r, sets, ignore_names);
  if (j.contains("expected")) expected(at.key("expected"), j["expected"], r, sets, expected_names);
  if (j.contains("pairs")) pair_rules(at.key("pairs"), j["pairs"], r);
  json canon = j;
  canon.erase("$schema");
  r.canonical = canon.dump() + "|" + units;  // std::map keys: sorted, whatever the file's order
  return r;
}

Rules load_rules_file(const std::string& path, const std::string& units) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open the rules file (--rules)");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  json doc;
  try {
    doc = parse_json_strict(text);
  } catch (const JsonTextError& e) {
    throw SceneError(path + ": invalid JSON" + (e.path.empty() ? "" : " at " + e.path) + ": " +
                     e.what());
  }
  return parse_rules(doc, path, "", units);
}

}  // namespace pd
