// The rules applied to a run's candidates (batch/rule_scope.h): out-of-scope
// and ignored candidates dropped and counted per rule, the checked ones given
// their rule's tolerance (the pair's own level first) and named tests and
// expected rule; rules_hash follows the rules and the parts' labels.
#include <gtest/gtest.h>

#include "batch/rule_scope.h"
#include "rule_scenes.h"

using namespace pd;
using pd::test::rule_part;
using pd::test::scene_with;

namespace {

// s1 and s2 structure in one weldment, p1 a system, q in no set.
const std::string kParts = rule_part("s1", R"("tags": ["st"], "group": "frame/w1")") + "," +
                           rule_part("s2", R"("tags": ["st"], "group": "frame/w1")") + "," +
                           rule_part("p1", R"("tags": ["sys"])") + "," +
                           rule_part("q", R"("tags": ["other"])");
const std::string kRules = R"({
    "sets": {"st": {"tags": ["st"]}, "sys": {"tags": ["sys"]}},
    "tests": [{"name": "st-sys", "a": "st", "b": "sys", "tolerance": 0.3},
              {"name": "self", "a": "st"}],
    "ignore": [{"name": "weld", "same": "group", "reason": "welded"}],
    "expected": [{"name": "seated", "a": "st", "b": "sys", "max_depth": 0.2, "reason": "r"}],
    "pairs": [{"pair": ["p1", "s2"], "tolerance": 0.7}]})";

}  // namespace

TEST(RuleScope, CandidatesAreScopedCountedAndNamed) {
  const SceneSpec s = scene_with(kParts, kRules);
  RuleScope scope(s, {});
  CandidatePairs c;
  c.pairs = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  c.all_pairs = 6;
  scope.apply(c);
  EXPECT_EQ(c.pairs, (std::vector<std::pair<int, int>>{{0, 2}, {1, 2}}));
  const RuleCoverage& cov = scope.coverage();
  EXPECT_EQ(cov.out_of_scope, 3);  // every pair of q
  EXPECT_EQ(cov.ignored, 1);       // s1, s2: one weldment
  EXPECT_EQ(cov.test_pairs, (std::vector<long>{2, 0}));
  EXPECT_EQ(cov.ignore_pairs, (std::vector<long>{1}));
  EXPECT_EQ(cov.expected_pairs, (std::vector<long>{2}));

  const auto checks = scope.pair_checks([](int, int) { return PairChecks{}; });
  const PairChecks test_level = checks(0, 2), pair_level = checks(1, 2);
  ASSERT_TRUE(test_level.tolerance);
  EXPECT_EQ(test_level.tolerance->value, 0.3);
  EXPECT_EQ(test_level.tolerance->source, "rule");
  EXPECT_EQ(test_level.tolerance->basis, "tests[\"st-sys\"]");
  ASSERT_TRUE(pair_level.tolerance);
  EXPECT_EQ(pair_level.tolerance->value, 0.7);  // the pair's own level beats the test's
  EXPECT_EQ(pair_level.tolerance->basis, "pairs[0]");

  PairResult r;
  r.a = 0;
  r.b = 2;
  scope.note(r);
  EXPECT_EQ(r.tests, (std::vector<std::string>{"st-sys"}));
  EXPECT_EQ(r.expected, "seated");
}

TEST(RuleScope, TheRulesHashFollowsRulesAndLabels) {
  const std::string h = rules_hash(scene_with(kParts, kRules));
  EXPECT_EQ(h, rules_hash(scene_with(kParts, kRules)));
  std::string other_rules = kRules;
  other_rules.replace(other_rules.find("0.3"), 3, "0.4");
  EXPECT_NE(h, rules_hash(scene_with(kParts, other_rules)));
  std::string other_group = kParts;
  other_group.replace(other_group.find("frame/w1"), 8, "frame/w9");
  EXPECT_NE(h, rules_hash(scene_with(other_group, kRules)));
}
