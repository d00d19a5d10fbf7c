// The JSON Lines writer (--format jsonl, write_jsonl.cpp) in process: a line
// per pair in report order, each its report entry with its review, then the
// summary line the streamed form also ends with.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "report_fixture.h"
#include "results/fingerprint.h"

using namespace pd;
using namespace pd::test;
using nlohmann::json;

namespace {

std::vector<json> lines_of(const std::string& text) {
  std::vector<json> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(json::parse(line));
  return out;
}

}  // namespace

TEST(WriteJsonl, ALinePerPairThenTheSummary) {
  ReportFixture f = every_status();
  const ReportInput in = f.input();
  const std::string text = render_jsonl(in);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  const std::vector<json> lines = lines_of(text);
  ASSERT_EQ(lines.size(), f.run.pairs.size() + 1);
  for (size_t k = 0; k < f.run.pairs.size(); ++k) {
    const PairResult& r = f.run.pairs[k];
    const json& j = lines[k];
    EXPECT_EQ(j["a"], f.run.parts[r.a].id);
    EXPECT_EQ(j["b"], f.run.parts[r.b].id);
    EXPECT_EQ(j["status"], status_name(r.status));
    EXPECT_EQ(j["fingerprint"], pair_fingerprint(j["a"], j["b"]));
    EXPECT_FALSE(j.contains("summary"));
  }
  // The two interferences share a fix: both carry the group's id.
  ASSERT_TRUE(lines[0].contains("group")) << lines[0].dump();
  EXPECT_EQ(lines[0]["group"], lines[3]["group"]);
  EXPECT_FALSE(lines[1].contains("group"));
  // The last line is the tail, as streamed.
  EXPECT_EQ(text.substr(text.rfind('\n', text.size() - 2) + 1), jsonl_tail(in) + "\n");
}

TEST(WriteJsonl, TheTailCountsAndNamesFailedParts) {
  ReportFixture f = every_status();
  const json tail = json::parse(jsonl_tail(f.input()));
  const json& s = tail["summary"];
  EXPECT_EQ(s["parts"], 5);
  EXPECT_EQ(s["part_errors"], 1);
  EXPECT_EQ(s["candidate_pairs"], 6);
  EXPECT_EQ(s["interference"], 2);
  EXPECT_EQ(s["false_positive"], 1);
  EXPECT_EQ(s["separated"], 1);
  EXPECT_EQ(s["undecided"], 1);
  EXPECT_EQ(s["error"], 1);
  EXPECT_EQ(s["exit_code"], 3);
  EXPECT_EQ(s["fail_on"], "interference");
  EXPECT_EQ(s["failing"], 2);
  EXPECT_EQ(tail["part_errors"],
            json::parse(R"([{"id": "bad", "error": "unreadable: no such file"}])"));
  ASSERT_EQ(tail["groups"].size(), 1u);
  EXPECT_EQ(tail["groups"][0]["members"].size(), 2u);
}

TEST(WriteJsonl, PartErrorsIsAnArrayEvenWhenEmpty) {
  ReportFixture f;
  f.part("a");
  f.part("b");
  f.pair(0, 1, Status::kSeparated, 0.0);
  const json tail = json::parse(jsonl_tail(f.input()));
  ASSERT_TRUE(tail.contains("part_errors"));
  EXPECT_TRUE(tail["part_errors"].is_array());
  EXPECT_TRUE(tail["part_errors"].empty());
  EXPECT_EQ(tail["summary"]["exit_code"], 0);
}
