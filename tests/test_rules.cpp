// Rules (issue 28) through the binary: the worked example
// testdata/examples/rules-assembly.json against what its boxes imply,
// unsharded and through shards and merge. The rules' modules alone:
// test_rule_glob.cpp, test_rules_json.cpp, test_rule_index.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "cli_support.h"

namespace {

using nlohmann::json;
using pd::test::kSource;
using pd::test::pdcheck;
using pd::test::read_text;
using pd::test::write_temp;

const std::string kExample = kSource + "/testdata/examples/rules-assembly.json";

// ---- the worked example, against its boxes ----

struct Box {
  double lo[3], hi[3];
};

std::map<std::string, Box> boxes_of(const json& scene) {
  std::map<std::string, Box> out;
  for (const json& p : scene["parts"]) {
    Box b{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
    for (const json& v : p["vertices"])
      for (int d = 0; d < 3; ++d) {
        b.lo[d] = std::min(b.lo[d], v[d].get<double>());
        b.hi[d] = std::max(b.hi[d], v[d].get<double>());
      }
    out[p["id"]] = b;
  }
  return out;
}

// The depth of two axis-aligned boxes: their smallest per-axis overlap (< 0: apart).
double box_depth(const Box& a, const Box& b) {
  double depth = 1e300;
  for (int d = 0; d < 3; ++d)
    depth = std::min(depth, std::min(a.hi[d], b.hi[d]) - std::max(a.lo[d], b.lo[d]));
  return depth;
}

std::string key(std::string a, std::string b) {
  if (b < a) std::swap(a, b);
  return a + "/" + b;
}

// Every field the example's truth names, checked on a report (a run's or a merge's).
void expect_example_report(const json& report, const json& truth) {
  const std::map<std::string, Box> boxes = boxes_of(json::parse(read_text(kExample)));
  // The boxes' own overlaps: the 8 candidates and the 28 culled pairs.
  long touching = 0;
  for (auto a = boxes.begin(); a != boxes.end(); ++a)
    for (auto b = std::next(a); b != boxes.end(); ++b)
      touching += box_depth(a->second, b->second) >= 0;
  EXPECT_EQ(touching, 8);
  std::map<std::string, json> reported;
  for (const json& p : report["pairs"]) reported[key(p["a"], p["b"])] = p;
  EXPECT_EQ(reported.size(), truth["pairs"].size());
  for (const auto& [k, want] : truth["pairs"].items()) {
    SCOPED_TRACE(k);
    ASSERT_TRUE(reported.count(k));
    const json& got = reported[k];
    const auto slash = k.find('/');
    const double geometric = box_depth(boxes.at(k.substr(0, slash)), boxes.at(k.substr(slash + 1)));
    EXPECT_NEAR(geometric, want["depth"].get<double>(), 1e-9);  // the truth file's arithmetic
    EXPECT_NEAR(got["depth"].get<double>(), geometric, 1e-6);
    // The status the depth implies against the pair's tolerance.
    const double tol = want["tolerance"];
    const std::string implied = geometric <= 1e-9  ? "separated"
                                : geometric <= tol ? "false_positive"
                                                   : "interference";
    EXPECT_EQ(implied, want["status"]);
    EXPECT_EQ(got["status"], want["status"]);
    EXPECT_EQ(got.value("tolerance", report["tolerance"].get<double>()), tol);
    EXPECT_EQ(got["tests"], want["tests"]);
    EXPECT_EQ(got.value("expected", ""), want.value("expected", ""));
    if (want.contains("suppressed_by")) {
      ASSERT_TRUE(got.contains("suppressed"));
      EXPECT_EQ(got["suppressed"]["rule"], want["suppressed_by"]);
      EXPECT_LE(got["depth"].get<double>(), got["suppressed"]["max_depth"].get<double>());
    } else {
      EXPECT_FALSE(got.contains("suppressed"));
    }
  }
  for (const auto& [k, why] : truth["not_checked"].items()) {
    const auto slash = k.find('/');
    EXPECT_GT(box_depth(boxes.at(k.substr(0, slash)), boxes.at(k.substr(slash + 1))), 0) << k;
    EXPECT_FALSE(reported.count(k)) << k << " is " << why;
  }
  for (const auto& [field, want] : truth["summary"].items())
    EXPECT_EQ(report["summary"][field], want) << "summary." << field;
  const json& rules = report["rules"];
  for (const json& s : rules["sets"])
    EXPECT_EQ(s["parts"], truth["sets"][s["name"].get<std::string>()]);
  for (const json& t : rules["tests"])
    EXPECT_EQ(t["pairs"], truth["tests"][t["name"].get<std::string>()]);
  for (const json& g : rules["ignore"])
    EXPECT_EQ(g["pairs"], truth["ignore"][g["name"].get<std::string>()]);
  for (const json& e : rules["expected"]) {
    const json& want = truth["expected"][e["name"].get<std::string>()];
    EXPECT_EQ(e["pairs"], want["pairs"]);
    EXPECT_EQ(e["suppressed"], want["suppressed"]);
    EXPECT_EQ(e["exceeded"], want["exceeded"]);
  }
  EXPECT_EQ(rules["out_of_scope"], truth["summary"]["out_of_scope"]);
  EXPECT_EQ(rules["ignored"], truth["summary"]["ignored"]);
  EXPECT_EQ(report["hashes"]["rules"].get<std::string>().size(), 32u);
}

json truth() {
  return json::parse(read_text(kSource + "/testdata/examples/rules-assembly.expected.json"));
}
TEST(RulesExample, ReportMatchesTheGeometry) {
  const std::string out = pd_test::process_dir() + "rules-example.json";
  const auto r = pdcheck(kExample + " -o " + out + " --jobs 1 --quiet");
  EXPECT_EQ(r.code, 1) << r.err;
  const json report = json::parse(read_text(out));
  expect_example_report(report, truth());
  // Parts carry their labels and the sets they are in.
  for (const json& p : report["parts"])
    if (p["id"] == "bolt-1") {
      EXPECT_EQ(p["tags"], json({"fastener"}));
      EXPECT_EQ(p["sets"], json({"fasteners"}));
    }
  bool skip = false;
  const std::string problems =
      pd::test::validate_json(kSource + "/docs/report.schema.json", out, skip);
  if (!skip) {
    EXPECT_EQ(problems, "");
  }
  const std::string scene_problems =
      pd::test::validate_json(kSource + "/docs/scene.schema.json", kExample, skip);
  if (!skip) {
    EXPECT_EQ(scene_problems, "");
  }
}

TEST(RulesExample, ShardsAndMergeCarryTheRules) {
  const std::string dir = pd_test::process_dir();
  for (int k = 1; k <= 3; ++k) {
    const auto r = pdcheck(kExample + " --shard " + std::to_string(k) + "/3 -o " + dir +
                           "rules-shard-" + std::to_string(k) + ".json --jobs 1 --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
  }
  const std::string merged = dir + "rules-merged.json";
  const auto m = pdcheck("merge " + dir + "rules-shard-1.json " + dir + "rules-shard-2.json " +
                         dir + "rules-shard-3.json -o " + merged + " --quiet");
  EXPECT_EQ(m.code, 1) << m.err;
  expect_example_report(json::parse(read_text(merged)), truth());
  // A shard written under other rules is refused, naming hashes.rules.
  json other = json::parse(read_text(dir + "rules-shard-2.json"));
  other["hashes"]["rules"] = std::string(32, '0');
  write_temp("rules-shard-2x.json", other.dump());
  const auto refused =
      pdcheck("merge " + dir + "rules-shard-1.json " + dir + "rules-shard-2x.json " + dir +
              "rules-shard-3.json -o " + dir + "x.json");
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.err.find("$.hashes.rules"), std::string::npos) << refused.err;
}

TEST(RulesExample, RulesFileEqualsTheSceneKey) {
  json scene = json::parse(read_text(kExample));
  json rules = scene["rules"];
  rules["$schema"] = "../../docs/rules.schema.json";
  scene.erase("rules");
  scene.erase("$schema");
  const std::string dir = pd_test::process_dir();
  const std::string rules_file = write_temp("rules-only.json", rules.dump(2));
  const std::string scene_file = write_temp("rules-scene.json", scene.dump());
  const auto r = pdcheck(scene_file + " --rules " + rules_file + " -o " + dir +
                         "rules-file-report.json --jobs 1 --quiet");
  EXPECT_EQ(r.code, 1) << r.err;
  const json with_file = json::parse(read_text(dir + "rules-file-report.json"));
  expect_example_report(with_file, truth());
  bool skip = false;
  const std::string problems =
      pd::test::validate_json(kSource + "/docs/rules.schema.json", rules_file, skip);
  if (!skip) {
    EXPECT_EQ(problems, "");
  }
  // Rules in two places are refused.
  const auto both = pdcheck(kExample + " --rules " + rules_file);
  EXPECT_EQ(both.code, 2);
  EXPECT_NE(both.err.find("give the rules in one place"), std::string::npos) << both.err;
  // A set that selects nothing: exit 2 naming the set and the file.
  rules["sets"]["hangers"].erase("optional");
  write_temp("rules-empty-set.json", rules.dump());
  const auto empty = pdcheck(scene_file + " --rules " + dir + "rules-empty-set.json");
  EXPECT_EQ(empty.code, 2);
  EXPECT_NE(
      empty.err.find("rules-empty-set.json: sets.hangers: the set \"hangers\" selects no part"),
      std::string::npos)
      << empty.err;
}

TEST(RulesExample, ReuseAndBaselineSayWhenTheRulesChanged) {
  const std::string dir = pd_test::process_dir();
  const std::string first = dir + "rules-first.json";
  ASSERT_EQ(pdcheck(kExample + " -o " + first + " --jobs 1 --quiet").code, 1);
  // The same rules: every pair reused, nothing said about rules.
  auto r = pdcheck(kExample + " --reuse " + first + " -o " + dir + "rules-again.json --jobs 1");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("6 pair(s) reused"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("rules"), r.err.find("rules-"));  // no warning naming the rules
  // structure-vs-systems at 0.2 mm: its two pairs are solved again, pipe-2 now interferes.
  json scene = json::parse(read_text(kExample));
  scene["rules"]["tests"][0]["tolerance"] = "0.2 mm";
  scene.erase("$schema");
  const std::string changed = write_temp("rules-changed.json", scene.dump());
  const std::string out = dir + "rules-changed-report.json";
  r = pdcheck(changed + " --reuse " + first + " --baseline " + first + " -o " + out + " --jobs 1");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--reuse " + first + ": written under other rules"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("--baseline " + first + ": written under other rules"), std::string::npos);
  EXPECT_NE(r.err.find("4 pair(s) reused"), std::string::npos) << r.err;
  const json report = json::parse(read_text(out));
  for (const json& p : report["pairs"])
    if (p["a"] == "pipe-2" || p["b"] == "pipe-2") {
      EXPECT_EQ(p["status"], "interference");
      EXPECT_EQ(p["tolerance"], 0.2);
      EXPECT_EQ(p["baseline_state"], "updated");  // was a false_positive
      EXPECT_FALSE(p.value("reused", false));
    }
}

}  // namespace
