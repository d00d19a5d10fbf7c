// Rules as data (docs/scene-format.md, "Rules"): named selection sets of parts,
// the tests that say which pairs are checked (A against B, or a set against
// itself) with their own tolerance or clearance, ignore rules and expected
// contacts. Given as the scene's `rules` key or a rules file (--rules FILE,
// docs/rules.schema.json); parsed strictly, every error naming the file and
// the JSON path. Resolved against the parts once (scene/rule_index.h).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace pd {

/// Which parts a set holds: a part matches when any listed field matches
/// (an id glob, one of the tags, a group glob).
struct RuleSet {
  std::string name;
  std::vector<std::string> ids;     ///< globs over part ids (`*` any run, `?` one character)
  std::vector<std::string> tags;    ///< exact tags
  std::vector<std::string> groups;  ///< globs over group paths (scene/rule_glob.h)
  bool optional = false;            ///< selecting no part is no error
  std::string where;                ///< "scene.json: rules.sets.bolts", for messages
};

/// A pair of sets (indices into Rules::sets); b < 0: a within a (a self test).
struct SetPair {
  int a = -1, b = -1;
  bool self() const { return b < 0; }
};

struct RuleTest {
  std::string name;
  SetPair sets;
  std::optional<double> tolerance;  ///< scene units
  std::optional<double> clearance;  ///< scene units, > 0
  std::string where;
};

/// Pairs not checked at all, counted: parts of one group, of one mesh file,
/// or a pair of sets.
struct IgnoreRule {
  enum class Same { kNone, kGroup, kFile };
  std::string name;  ///< given, else "ignore[k]"
  Same same = Same::kNone;
  SetPair sets;  ///< when same is kNone
  std::string reason;
  std::string where;
};

/// Pairs that may overlap up to max_depth: such a finding is reported
/// suppressed (naming the rule) and does not fail the run; deeper is a finding.
struct ExpectedRule {
  std::string name;  ///< given, else "expected[k]"
  SetPair sets;
  double max_depth = 0.0;  ///< scene units, >= 0
  std::string reason;
  std::string where;
};

/// The most specific level of the tolerance hierarchy: one named pair of parts.
struct PairRule {
  std::string a, b;  ///< part ids
  std::optional<double> tolerance, clearance;
  std::string where;
};

struct Rules {
  std::string source;  ///< "scene.json: rules" or the rules file's path
  std::vector<RuleSet> sets;
  std::vector<RuleTest> tests;
  std::vector<IgnoreRule> ignore;
  std::vector<ExpectedRule> expected;
  std::vector<PairRule> pairs;
  std::string canonical;  ///< the rules as read, keys sorted (for hashes.rules)
  std::string units;      ///< the scene unit every length was converted to
};

/// Reads a rules object. `file` and `at` ("rules" in a scene, "" in a rules
/// file) name errors: "scene.json: rules.tests[1].b: unknown set \"bolt\"".
/// Lengths are numbers in `units` or strings with a unit suffix ("0.2 mm").
/// Throws SceneError (exit 2).
Rules parse_rules(const nlohmann::json& j, const std::string& file, const std::string& at,
                  const std::string& units);

/// A rules file (--rules FILE): the same object at its root, optionally with
/// "$schema". Throws SceneError naming the file.
Rules load_rules_file(const std::string& path, const std::string& units);

}  // namespace pd
