// The report document (report_json.cpp): a run's counts, the summary's keys
// and their order, the stderr summary line, the method block and the optional
// sections, on hand-made runs.
#include <gtest/gtest.h>

#include "report/report_json.h"
#include "report_fixture.h"

using namespace pd;
using namespace pd::test;

namespace {

std::vector<std::string> keys(const nlohmann::ordered_json& j) {
  std::vector<std::string> out;
  for (const auto& [k, v] : j.items()) out.push_back(k);
  return out;
}

}  // namespace

TEST(ReportJson, SummarizeCountsEveryStatusAndFailedPart) {
  ReportFixture f = every_status();
  f.run.culled = 7;
  const Summary s = summarize(f.run);
  EXPECT_EQ(s.parts, 5);
  EXPECT_EQ(s.part_errors, 1);
  EXPECT_EQ(s.all_pairs, 10);
  EXPECT_EQ(s.culled, 7);
  EXPECT_EQ(s.unchecked, 4);
  EXPECT_EQ(s.candidates, 6);
  EXPECT_EQ(s.interference, 2);
  EXPECT_EQ(s.false_positive, 1);
  EXPECT_EQ(s.separated, 1);
  EXPECT_EQ(s.undecided, 1);
  EXPECT_EQ(s.error, 1);
  EXPECT_FALSE(s.clearance_checked);
  EXPECT_FALSE(s.rules_given);
  f.run.simulated.push_back("clearance");
  f.run.rules = RuleCoverage{};
  f.run.rules->out_of_scope = 3;
  f.run.rules->ignored = 2;
  const Summary r = summarize(f.run);
  EXPECT_TRUE(r.clearance_checked);
  EXPECT_TRUE(r.rules_given);
  EXPECT_EQ(r.out_of_scope, 3);
  EXPECT_EQ(r.ignored, 2);
}

TEST(ReportJson, SummaryKeysInTheirOrder) {
  Summary s;
  s.parts = 2;
  s.interference = 1;
  const std::vector<std::string> plain = {
      "parts",     "part_errors",    "pairs",        "culled", "unchecked", "candidate_pairs",
      "separated", "false_positive", "interference", "error",  "undecided", "exit_code"};
  EXPECT_EQ(keys(summary_json(s)), plain);
  EXPECT_EQ(summary_json(s)["exit_code"], 1);
  // A run that checked clearances shows their count; one with rules, after the
  // culled pairs, the candidates the rules kept out.
  s.clearance_checked = true;
  s.rules_given = true;
  s.out_of_scope = 4;
  const nlohmann::ordered_json j = summary_json(s);
  const std::vector<std::string> full = {
      "parts",     "part_errors",         "pairs",     "culled",         "out_of_scope", "ignored",
      "unchecked", "candidate_pairs",     "separated", "false_positive", "interference", "error",
      "undecided", "clearance_violation", "exit_code"};
  EXPECT_EQ(keys(j), full);
  EXPECT_EQ(j["out_of_scope"], 4);
  s.error = 1;  // incomplete wins
  EXPECT_EQ(summary_json(s)["exit_code"], 3);
}

TEST(ReportJson, SummaryLineSaysWhatWasFound) {
  Summary s;
  s.parts = 12;
  s.candidates = 7;
  s.culled = 59;
  s.interference = 1;
  s.false_positive = 2;
  s.separated = 4;
  EXPECT_EQ(summary_line(s, 1.234),
            "pdcheck: 12 parts, 7 candidate pairs (59 culled): 1 interference, 2 false_positive, "
            "4 separated, 0 error in 1.23 s");
  s.clearance_checked = true;
  s.clearance_violation = 3;
  s.undecided = 1;
  s.part_errors = 2;
  s.unchecked = 5;
  s.rules_given = true;
  s.out_of_scope = 6;
  s.ignored = 8;
  EXPECT_EQ(summary_line(s, 0),
            "pdcheck: 12 parts, 7 candidate pairs (59 culled, 6 out of scope, 8 ignored, 5 "
            "unchecked): 1 interference, 3 clearance_violation, 2 false_positive, 4 separated, 1 "
            "undecided, 0 error, 2 part(s) unusable in 0.00 s");
}

TEST(ReportJson, MethodShowsTheSettingsOfItsMethodOnly) {
  SolverSettings s;
  const nlohmann::ordered_json mlsl = method_json(s);
  EXPECT_EQ(keys(mlsl), (std::vector<std::string>{"name", "seed", "samples", "reduced", "sigma",
                                                  "tau", "link_scale"}));
  EXPECT_EQ(mlsl["name"], method_name(Method::kMlsl));
  EXPECT_EQ(mlsl["samples"], s.samples);
  s.method = Method::kGrid;
  s.grid = 17;
  const nlohmann::ordered_json grid = method_json(s);
  EXPECT_EQ(keys(grid), (std::vector<std::string>{"name", "seed", "grid"}));
  EXPECT_EQ(grid["grid"], 17);
  s.method = Method::kExact;
  EXPECT_EQ(keys(method_json(s)), (std::vector<std::string>{"name", "seed"}));
}

TEST(ReportJson, OptionalSectionsOnlyWhenTheRunHasThem) {
  ReportFixture f = every_status();
  nlohmann::ordered_json doc = report_json(f.context, f.run);
  for (const char* key : {"hashes", "shard", "rules", "tolerance_auto"})
    EXPECT_FALSE(doc.contains(key)) << key;
  EXPECT_EQ(doc["report_version"], 1);
  EXPECT_EQ(doc["tool"]["name"], "pdcheck");
  EXPECT_EQ(doc["pairs"][0]["a"], "frame");
  EXPECT_EQ(doc["pairs"][0]["b"], "lid <&>");
  f.run.scene_hash = "s1";
  f.run.settings_hash = "h1";
  f.run.shard = ShardManifest{};
  f.run.shard->shard = {2, 3};
  f.run.shard->owned = {1, 4};
  f.context.auto_tolerance = AutoTolerance{};
  f.context.auto_tolerance->min = 0.01;
  doc = report_json(f.context, f.run);
  EXPECT_EQ(doc["hashes"]["scene"], "s1");
  EXPECT_EQ(doc["hashes"]["settings"], "h1");
  EXPECT_EQ(doc["shard"]["index"], 2);
  EXPECT_EQ(doc["shard"]["total"], 3);
  EXPECT_EQ(doc["shard"]["owned"], nlohmann::ordered_json({1, 4}));
  EXPECT_EQ(doc["tolerance_auto"], nlohmann::ordered_json({{"min", 0.01}}));
  // A part's box is where exports aim; a failed part has none.
  EXPECT_TRUE(doc["parts"][0].contains("box")) << doc["parts"][0].dump();
  EXPECT_FALSE(doc["parts"][4].contains("box")) << doc["parts"][4].dump();
}
