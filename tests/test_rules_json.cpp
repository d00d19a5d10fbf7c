// The rules block of a scene (rules_json.cpp): strict reading with the file
// and JSON path in every error, lengths with unit suffixes.
#include <gtest/gtest.h>

#include "rule_scenes.h"
#include "scene/scene.h"

namespace {

using pd::test::rule_part;
using pd::test::scene_error_of;
using pd::test::scene_with;

TEST(RulesJson, StrictWithFileAndPath) {
  const std::string parts = rule_part("a", R"("tags": ["x"])");
  EXPECT_EQ(scene_error_of([&] { scene_with(parts, R"({"sets": {"s": {"tag": ["x"]}}})"); }),
            "s.json: rules.sets.s.tag: unknown key (allowed: groups, ids, optional, tags)");
  EXPECT_EQ(scene_error_of([&] {
              scene_with(parts, R"({"sets": {"s": {"tags": ["x"]}}, "tests": [{"name": "t",
                          "a": "s", "b": "q"}]})");
            }),
            "s.json: rules.tests[0].b: unknown set \"q\" (sets: s)");
  EXPECT_EQ(scene_error_of([&] { scene_with(parts, R"({"ignore": [{"same": "group"}]})"); }),
            "s.json: rules.ignore[0]: missing \"reason\" (say why these pairs are not checked)");
  EXPECT_NE(scene_error_of([&] {
              scene_with(parts, R"({"sets": {"s": {"tags": ["x"]}}, "tests": [{"name": "t",
                          "a": "s", "tolerance": "0.2 furlong"}]})");
            }).find("rules.tests[0].tolerance: expected a length"),
            std::string::npos);
  // A clearance refines the scene's clearance check, which must be there.
  EXPECT_NE(scene_error_of([&] {
              scene_with(parts, R"({"sets": {"s": {"tags": ["x"]}}, "tests": [{"name": "t",
                          "a": "s", "clearance": 2}]})");
            }).find("rules.tests[0]: clearance: a rule's clearance refines"),
            std::string::npos);
  EXPECT_NE(scene_error_of([&] {
              scene_with(rule_part("a", R"("group": "w//r")"), "{}");
            }).find("parts[0].group: expected a path"),
            std::string::npos);
}

TEST(RulesJson, LengthsTakeUnitSuffixes) {
  const pd::SceneSpec s = pd::parse_scene_json(
      R"({"units": "in", "tolerance": 0.01, "parts": [{"id": "a", "tags": ["x"], "vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]]}],
          "rules": {"sets": {"s": {"tags": ["x"]}}, "tests": [{"name": "t", "a": "s", "tolerance": "0.254 mm"}],
                    "expected": [{"a": "s", "max_depth": 0.5, "reason": "r"}]}})",
      "s.json", "");
  ASSERT_TRUE(s.rules);
  EXPECT_NEAR(*s.rules->tests[0].tolerance, 0.01, 1e-15);  // 0.254 mm in inches
  EXPECT_EQ(s.rules->expected[0].max_depth, 0.5);          // a bare number: scene units
  EXPECT_EQ(s.rules->expected[0].name, "expected[0]");
}
}  // namespace
