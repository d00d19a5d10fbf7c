// The JSON report writer (--format json, write_json.cpp) in process: the
// report with its review, valid against docs/report.schema.json.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "bcf_check.h"
#include "cli_support.h"
#include "report_fixture.h"

using namespace pd;
using namespace pd::test;
using nlohmann::json;

TEST(WriteJson, EveryStatusValidatesAgainstTheSchema) {
  ReportFixture f = every_status();
  const std::string path = process_temp("report.json");
  std::ofstream(path) << render_json(f.input());
  bool skip = false;
  const std::string errors = validate_json(kSource + "/docs/report.schema.json", path, skip);
  PD_REQUIRE_TOOL(!skip, "python3-jsonschema");
  EXPECT_EQ(errors, "");
}

TEST(WriteJson, TheDocumentCarriesTheReview) {
  ReportFixture f = every_status();
  const ReportInput in = f.input();
  const nlohmann::ordered_json doc = report_document(in);
  EXPECT_EQ(render_json(in), doc.dump(2) + "\n");
  EXPECT_EQ(doc["scene"], "scene.json");
  EXPECT_EQ(doc["units"], "mm");
  EXPECT_EQ(doc["tolerance"], 0.1);
  ASSERT_EQ(doc["pairs"].size(), f.run.pairs.size());
  ASSERT_EQ(doc["parts"].size(), f.run.parts.size());
  EXPECT_EQ(doc["parts"][4]["error"], "unreadable: no such file");
  // The review's verdict, not the summary's own: the same exit code here (3).
  EXPECT_EQ(doc["summary"]["exit_code"], f.review.exit_code);
  EXPECT_EQ(doc["summary"]["exit_code"], 3);
  EXPECT_EQ(doc["summary"]["failing"], 2);
  ASSERT_EQ(doc["groups"].size(), 1u);
  const std::string group = doc["groups"][0]["id"];
  EXPECT_EQ(doc["pairs"][0]["group"], group);
  EXPECT_EQ(doc["pairs"][3]["group"], group);
  // No baseline, no suppressions: neither section, nor any pair's state.
  EXPECT_FALSE(doc.contains("baseline"));
  EXPECT_FALSE(doc.contains("suppressions"));
  for (const auto& p : doc["pairs"]) EXPECT_FALSE(p.contains("baseline_state")) << p.dump();
}

TEST(WriteJson, FailOnNoneLeavesTheFindingsPassing) {
  ReportFixture f = every_status();
  f.run.pairs.pop_back();  // the failed pair, the undecided one and the bad part: all checked
  f.run.pairs.erase(f.run.pairs.begin() + 4);
  f.run.parts[4].error.reset();
  f.run.unchecked = 0;
  f.options.fail_on = FailOn::kNone;
  const nlohmann::ordered_json doc = report_document(f.input());
  EXPECT_EQ(doc["summary"]["fail_on"], "none");
  EXPECT_EQ(doc["summary"]["failing"], 0);
  EXPECT_EQ(doc["summary"]["exit_code"], 0);
  EXPECT_EQ(doc["summary"]["interference"], 2);
}
