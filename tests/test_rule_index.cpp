// The rules resolved against a scene's parts (rule_index.cpp): sets, scope,
// ignore and expected rules, and the tolerance hierarchy, pair by pair.
#include <gtest/gtest.h>

#include "rule_scenes.h"
#include "scene/rule_index.h"
#include "scene/scene.h"

namespace {

using pd::test::rule_part;
using pd::test::scene_error_of;
using pd::test::scene_with;

TEST(RuleIndex, EmptySetIsAnErrorUnlessOptional) {
  const std::string parts = rule_part("a", R"("tags": ["x"])") + "," + rule_part("b", "");
  pd::SceneSpec s =
      scene_with(parts, R"({"sets": {"bolts": {"ids": ["bolt-*"]}, "x": {"tags": ["x"]}}})");
  const std::string e = scene_error_of([&] { pd::RuleIndex(*s.rules, s.parts); });
  EXPECT_NE(e.find("s.json: rules.sets.bolts: the set \"bolts\" selects no part"),
            std::string::npos)
      << e;
  s = scene_with(parts, R"({"sets": {"bolts": {"ids": ["bolt-*"], "optional": true}}})");
  EXPECT_EQ(scene_error_of([&] { pd::RuleIndex(*s.rules, s.parts); }), "(no error)");
}

TEST(RuleIndex, ScopeIgnoreExpectedAndToleranceHierarchy) {
  const std::string parts = rule_part("s1", R"("tags": ["st"], "group": "frame/w1")") + "," +
                            rule_part("s2", R"("tags": ["st"], "group": "frame/w1")") + "," +
                            rule_part("s3", R"("tags": ["st"], "group": "frame/w2")") + "," +
                            rule_part("p1", R"("tags": ["sys"])") + "," +
                            rule_part("p2", R"("tags": ["sys"])");
  const pd::SceneSpec s = scene_with(parts, R"({
    "sets": {"st": {"tags": ["st"]}, "sys": {"tags": ["sys"]}, "w2": {"groups": ["frame/w2"]},
             "all": {"ids": ["*"]}},
    "tests": [{"name": "coarse", "a": "st", "b": "sys", "tolerance": 0.3},
              {"name": "fine", "a": "all", "b": "sys", "tolerance": 0.1},
              {"name": "self", "a": "st"}],
    "ignore": [{"same": "group", "reason": "welded"}],
    "expected": [{"name": "e1", "a": "w2", "b": "sys", "max_depth": 0.2, "reason": "r"},
                 {"name": "e2", "a": "st", "b": "sys", "max_depth": 0.4, "reason": "r"}],
    "pairs": [{"pair": ["p1", "s1"], "tolerance": 0.7}]})");
  const pd::RuleIndex index(*s.rules, s.parts);
  using Scope = pd::PairDecision::Scope;
  // s1 against p2: both tests cover it; equal rank, the smaller tolerance wins.
  pd::PairDecision d = index.decide(0, 4);
  EXPECT_EQ(d.scope, Scope::kChecked);
  EXPECT_EQ(d.tests, (std::vector<int>{0, 1}));
  EXPECT_EQ(d.tolerance, 0.1);
  EXPECT_EQ(index.tolerance_rule(d), "tests[\"fine\"]");
  EXPECT_EQ(d.expected, 1);  // e2: s1 is not in w2
  // The pair's own level beats every test, whatever its value.
  d = index.decide(3, 0);
  EXPECT_EQ(d.tolerance, 0.7);
  EXPECT_EQ(index.tolerance_rule(d), "pairs[0]");
  // The first expected rule covering the pair is its.
  EXPECT_EQ(index.decide(2, 3).expected, 0);
  // Same group: ignored; another group: checked by the self test, no tolerance of its own.
  d = index.decide(0, 1);
  EXPECT_EQ(d.scope, Scope::kIgnored);
  d = index.decide(1, 2);
  EXPECT_EQ(d.scope, Scope::kChecked);
  EXPECT_EQ(d.tests, (std::vector<int>{2}));
  EXPECT_FALSE(d.tolerance);
  // Systems against systems: "fine" needs one side in sys and the other in all: covered;
  EXPECT_EQ(index.decide(3, 4).scope, Scope::kChecked);
  EXPECT_EQ(index.sets_of(2), (std::vector<std::string>{"all", "st", "w2"}));
}

TEST(RuleIndex, OutOfScopeWhenNoTestCovers) {
  const pd::SceneSpec s =
      scene_with(rule_part("a", R"("tags": ["x"])") + "," + rule_part("b", R"("tags": ["y"])") +
                     "," + rule_part("c", R"("tags": ["y"])"),
                 R"({"sets": {"x": {"tags": ["x"]}, "y": {"tags": ["y"]}},
                     "tests": [{"name": "x-y", "a": "x", "b": "y"}]})");
  const pd::RuleIndex index(*s.rules, s.parts);
  EXPECT_EQ(index.decide(0, 1).scope, pd::PairDecision::Scope::kChecked);
  EXPECT_EQ(index.decide(2, 0).scope, pd::PairDecision::Scope::kChecked);
  EXPECT_EQ(index.decide(1, 2).scope, pd::PairDecision::Scope::kOutOfScope);
}

}  // namespace
