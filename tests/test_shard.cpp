// Sharding end to end through the binary (docs/scale-out.md): shards 1..N of a
// scene with every status, part and pair errors and clearance checks, merged,
// equal the unsharded report; bad shard sets are refused; --shard auto reads
// CI and Slurm variables; GNU parallel runs the shards; --reuse re-solves
// exactly the pairs of a moved part.
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "batch/shard.h"
#include "cli_support.h"
#include "cube_json.h"
#include "page_data.h"

using nlohmann::json;
using namespace pd::test;

using pd_test::cube_json;

namespace {

// The environment of a run that is no CI or Slurm job, whatever runs the tests.
const std::string kNoShardEnv =
    "env -u CI_NODE_INDEX -u CI_NODE_TOTAL -u SLURM_ARRAY_TASK_ID -u SLURM_ARRAY_TASK_MIN "
    "-u SLURM_ARRAY_TASK_COUNT ";

// Groups 20 apart along x, each one relation between cubes of size 4 (a, b, and
// c for a chain): interference (0.5 in), 0.05 in (within the tolerance 0.1: a
// clearance violation with a depth), touching (a clearance violation at distance
// 0), 0.3 apart (a clearance violation at min 0.5), 0.7 apart
// (checked: the reach is 1.0 from a per-pair minimum), a chain of three
// overlapping cubes, 5 apart (culled). Plus a mesh part interfering with group 0,
// an unreadable mesh and a mesh with NaN coordinates (part errors: exit 3).
// `shift` moves part g2a along y.
std::string scene(const std::string& name, double shift = 0.0, int groups = 14) {
  const double offsets[] = {3.5, 3.95, 4.0, 4.3, 4.7, 3.0, 9.0};
  json parts = json::array();
  for (int g = 0; g < groups; ++g) {
    const double x = 20.0 * g, y = (g % 3) * 2.0;
    const std::string id = "g" + std::to_string(g);
    parts.push_back(cube_json(id + "a", x, y + (g == 2 ? shift : 0.0), 0, 4));
    parts.push_back(cube_json(id + "b", x + offsets[g % 7], y + 0.5, 0.5, 4));
    if (g % 7 == 5) parts.push_back(cube_json(id + "c", x + 1.5, y + 2.0, 3.0, 4));
  }
  // Just beyond the reach (1.0): culled by the exact box test, planned by the
  // shards' widened boxes, so the shards' own test must drop it.
  parts.push_back(cube_json("near_a", 400, 0, 0, 4));
  parts.push_back(cube_json("near_b", 405.00000003, 0, 0, 4));
  const std::string dir = kSource + "/testdata/formats/";
  parts.push_back({{"id", "boxmesh"},
                   {"mesh", dir + "box.obj"},
                   {"transform", {1, 0, 0, 1.5, 0, 1, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1}}});
  parts.push_back({{"id", "unreadable"}, {"mesh", dir + "garbage.stl"}});
  parts.push_back({{"id", "nanpart"}, {"mesh", dir + "nan.obj"}});
  const json checks = {
      {"clearance", {{"min", 0.5}, {"pairs", {{{"pair", {"g4a", "g4b"}}, {"min", 1.0}}}}}}};
  return write_temp(
      name, json{{"units", "mm"}, {"tolerance", 0.1}, {"checks", checks}, {"parts", parts}}.dump());
}

json read_json(const std::string& path);

// Seven groups and no part errors (the unreadable and NaN meshes left out).
std::string clean_scene(const std::string& name) {
  const std::string s = scene(name, 0.0, 7);
  json doc = read_json(s);
  auto& parts = doc["parts"];
  parts.erase(
      std::remove_if(parts.begin(), parts.end(),
                     [](const json& p) { return p["id"] == "unreadable" || p["id"] == "nanpart"; }),
      parts.end());
  std::ofstream(s) << doc.dump();
  return s;
}

// A worker crash on one pair: an error pair in every run that checks it.
const std::string kCrash = "PDCHECK_TEST_CRASH_PAIR=g7a:g7b ";

CliResult run(const std::string& args, const std::string& env = kCrash) {
  return shell(kNoShardEnv + env + pd_test::pdcheck_binary_for(env) + " " + args);
}

json read_json(const std::string& path) {
  return json::parse(read_text(path));
}

// A report without what differs between runs of the same work: timings.
json timeless(json d) {
  d.erase("seconds");
  d.erase("stage_seconds");
  for (auto& p : d["pairs"]) p.erase("time_ms");
  for (auto& p : d["parts"]) p.erase("decomposition_seconds");
  return d;
}

void expect_same_report(const json& got, const json& want, const std::string& what) {
  const json g = timeless(got), w = timeless(want);
  if (g == w) return;
  ADD_FAILURE() << what << " differs from the unsharded report";
  for (const auto& key : {"summary", "parts", "pairs"})
    if (g[key] != w[key]) {
      if (g[key].is_array() && g[key].size() == w[key].size()) {
        for (size_t k = 0; k < g[key].size(); ++k)
          if (g[key][k] != w[key][k]) {
            ADD_FAILURE() << key << "[" << k << "]: " << g[key][k].dump() << "\n  vs  "
                          << w[key][k].dump();
            break;
          }
      } else {
        ADD_FAILURE() << key << ": " << g[key].dump().substr(0, 2000) << "\n  vs  "
                      << w[key].dump().substr(0, 2000);
      }
    }
  for (const auto& [k, v] : w.items())
    if (!g.contains(k) || g[k] != v) ADD_FAILURE() << "top-level " << k << " differs";
}

std::string tmp(const std::string& name) {
  return testing::TempDir() + "shard_" + std::to_string(getpid()) + "_" + name;
}

// Runs shards 1..n of `scene_path`; returns their report paths.
std::vector<std::string> run_shards(const std::string& scene_path, int n, const std::string& tag,
                                    const std::string& extra = "",
                                    const std::string& env = kCrash) {
  std::vector<std::string> out;
  for (int k = 1; k <= n; ++k) {
    const std::string path =
        tmp(tag + "_" + std::to_string(k) + "of" + std::to_string(n) + ".json");
    const CliResult r = run(scene_path + " -q --jobs 2 --shard " + std::to_string(k) + "/" +
                                std::to_string(n) + " -o " + path + " " + extra,
                            env);
    EXPECT_EQ(r.code, 0) << "shard " << k << "/" << n << ": " << r.err;
    out.push_back(path);
  }
  return out;
}

std::string run_shard(const std::string& scene_path, int k, int n, const std::string& tag,
                      const std::string& extra = "") {
  const std::string path = tmp(tag + "_" + std::to_string(k) + "of" + std::to_string(n) + ".json");
  const CliResult r = run(scene_path + " -q --jobs 2 --shard " + std::to_string(k) + "/" +
                          std::to_string(n) + " -o " + path + " " + extra);
  EXPECT_EQ(r.code, 0) << r.err;
  return path;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += " " + x;
  return s;
}

}  // namespace

TEST(Shard, MergedShardsEqualTheUnshardedReport) {
  const std::string s = scene("shard_scene.json");
  const std::string full = tmp("full.json");
  const CliResult f = run(s + " -q --jobs 2 -o " + full);
  ASSERT_EQ(f.code, 3) << f.err;  // part errors and a crashed pair
  const json want = read_json(full);
  // The scene has what the merge must get right.
  const json& sum = want["summary"];
  for (const char* k : {"separated", "interference", "error", "clearance_violation", "part_errors",
                        "unchecked", "culled"})
    EXPECT_GT(sum[k].get<long>(), 0) << k << " missing from the test scene: " << sum.dump();
  // Every finding says where it is; groups of several findings (the chains of
  // three cubes: two of them ask the top cube to move up) are recomputed by the
  // merge from the merged set (compared below with the rest of the report).
  size_t several = 0;
  for (const auto& g : want["groups"]) several += g["members"].size() > 1 ? 1 : 0;
  EXPECT_GT(several, 0u) << want["groups"].dump();
  for (const auto& p : want["pairs"]) {
    const std::string st = p["status"];
    if (st == "false_positive" || st == "interference" || st == "clearance_violation") {
      EXPECT_TRUE(p.contains("at")) << p.dump();
    }
    EXPECT_EQ(p.contains("group"), st == "interference" || st == "clearance_violation") << p.dump();
  }

  for (int n : {1, 2, 3, 7}) {
    const std::vector<std::string> shards = run_shards(s, n, "eq");
    long checked = 0, planned = 0;
    std::set<long> owned;
    for (const auto& path : shards) {
      const json d = read_json(path);
      EXPECT_EQ(d["shard"]["total"], n);
      checked += d["shard"]["pairs_checked"].get<long>();
      planned += d["shard"]["pairs_planned"].get<long>();
      for (const auto& o : d["shard"]["owned"]) EXPECT_TRUE(owned.insert(o.get<long>()).second);
      if (n > 1) {
        EXPECT_LT(d["shard"]["vertices_loaded"].get<long>(),
                  d["shard"]["vertices_total"].get<long>())
            << path << ": a shard of " << n << " loaded every part";
      }
    }
    EXPECT_EQ(checked, sum["candidate_pairs"].get<long>()) << n << " shards";
    EXPECT_GT(planned, checked) << "the near pair must be planned and dropped";
    EXPECT_EQ(owned.size(), want["parts"].size());
    const std::string merged = tmp("merged" + std::to_string(n) + ".json");
    // Any order of the shard files.
    std::vector<std::string> reversed(shards.rbegin(), shards.rend());
    const CliResult m = run("merge" + joined(reversed) + " -o " + merged, "");
    EXPECT_EQ(m.code, f.code) << n << " shards: " << m.err;
    expect_same_report(read_json(merged), want, std::to_string(n) + " shards merged");
  }
}

TEST(Shard, MergeExitCodeIsTheRunsWithoutErrors) {
  // No part or pair errors: exit 1 (interference) from the run and from the merge.
  const std::string s = clean_scene("shard_clean.json");
  const std::string full = tmp("clean_full.json");
  const CliResult f = run(s + " -q -o " + full, "");
  ASSERT_EQ(f.code, 1) << f.err;
  const auto shards = run_shards(s, 3, "clean", "", "");
  const std::string merged = tmp("clean_merged.json");
  const CliResult m = run("merge" + joined(shards) + " -o " + merged, "");
  EXPECT_EQ(m.code, 1) << m.err;
  expect_same_report(read_json(merged), read_json(full), "clean scene, 3 shards");
  // Each shard exited 0 (run_shards), and its report says so: the verdict is
  // the merge's, also for the shards holding the findings.
  int with_findings = 0;
  for (int k = 1; k <= 3; ++k) {
    const auto summary = read_json(shards[k - 1])["summary"];
    EXPECT_EQ(summary["exit_code"], 0) << k;
    EXPECT_EQ(summary["verdict"], "deferred to pdcheck merge") << k;
    if (summary["failing"].get<long>() > 0) with_findings = k;
  }
  ASSERT_GT(with_findings, 0);
  EXPECT_FALSE(read_json(merged)["summary"].contains("verdict"));
  const CliResult said = run(
      s + " --jobs 2 --shard " + std::to_string(with_findings) + "/3 -o " + tmp("clean_said.json"),
      "");
  EXPECT_EQ(said.code, 0) << said.err;
  EXPECT_NE(said.err.find("(exit code 1 for this shard alone) is pdcheck merge's"),
            std::string::npos)
      << said.err;
  // Shard and merged reports follow the report schema.
  for (const std::string& doc : {shards[0], merged}) {
    bool skip = false;
    const std::string err = validate_json(kSource + "/docs/report.schema.json", doc, skip);
    if (skip) GTEST_SKIP() << "python3-jsonschema is not installed (scripts/setup.sh installs it)";
    EXPECT_EQ(err, "") << doc;
  }
  // --fail-on none: the run's own bar, applied by the merge.
  EXPECT_EQ(run("merge" + joined(shards) + " -q --fail-on none", "").code, 0);
}

namespace {

// Moves part `id` of a scene document by dx along x.
void move_part(json& doc, const std::string& id, double dx) {
  for (auto& p : doc["parts"])
    if (p["id"] == id)
      for (auto& v : p["vertices"]) v[0] = v[0].get<double>() + dx;
}

// The data an HTML page shows (its JSON island), without the run's timings.
json timeless_page_data(const std::string& path) {
  json d = pd::page_data(read_text(path));
  if (d.is_null()) return d;
  d.erase("seconds");
  d.erase("stage_seconds");
  return d;
}

// JUnit without its time attributes.
std::string without_times(std::string xml) {
  for (size_t at = xml.find(" time=\""); at != std::string::npos; at = xml.find(" time=\"", at)) {
    const size_t end = xml.find('"', at + 7);
    xml.erase(at, end + 1 - at);
  }
  return xml;
}

}  // namespace

// pdcheck merge writes what the run writes (docs/scale-out.md): the review of a
// baseline and suppressions in the report, the exit code under each bar, JUnit,
// SARIF, a starting suppressions file and the HTML page.
TEST(Shard, MergeWritesTheRunsCiOutputs) {
  const std::string s = clean_scene("shard_ci.json");
  const json doc = read_json(s);
  // Last week's assembly: g0 deeper (updated now), g1 apart (its finding new
  // now), g6 overlapping (absent now: culled).
  json old = doc;
  move_part(old, "g0b", -0.5);
  move_part(old, "g1b", 1.0);
  move_part(old, "g6b", -6.0);
  const std::string old_scene = write_temp("shard_ci_old.json", old.dump());
  const std::string baseline = tmp("ci_baseline.json"), written = tmp("ci_written.json");
  ASSERT_EQ(run(old_scene + " -q -o " + baseline + " --write-suppressions " + written, "").code, 1);
  // Reviewed: every finding of last week accepted (g6's entry goes stale now).
  json sup = read_json(written);
  ASSERT_GE(sup["suppressions"].size(), 2u) << sup.dump();
  for (auto& e : sup["suppressions"]) e["reason"] = "accepted in review";
  const std::string suppressions = write_temp("shard_ci_sup.json", sup.dump());

  const std::string ci = " --baseline " + baseline + " --suppressions " + suppressions;
  auto outputs = [&](const std::string& tag) {
    return " --junit " + tmp(tag + ".xml") + " --sarif " + tmp(tag + ".sarif") + " --html " +
           tmp(tag + ".html") + " --write-suppressions " + tmp(tag + "_sup.json");
  };
  const CliResult f = run(s + " -o " + tmp("ci_full.json") + ci + outputs("ci_full"), "");
  const auto shards = run_shards(s, 3, "ci", "", "");
  const CliResult m = run(
      "merge" + joined(shards) + " -o " + tmp("ci_merged.json") + ci + outputs("ci_merged"), "");
  ASSERT_EQ(f.code, 1) << f.err;  // the stale g6 entry
  EXPECT_EQ(m.code, f.code) << m.err;
  const json want = read_json(tmp("ci_full.json"));
  expect_same_report(read_json(tmp("ci_merged.json")), want, "3 shards merged with a review");
  // The review has all it is meant to show.
  std::set<std::string> states;
  for (const auto& p : want["pairs"])
    if (p.contains("baseline_state")) states.insert(p["baseline_state"].get<std::string>());
  for (const char* st : {"new", "unchanged", "updated"})
    EXPECT_TRUE(states.count(st)) << st << " missing from " << want["pairs"].dump();
  EXPECT_NE(want.dump().find("\"absent\""), std::string::npos);
  EXPECT_NE(want.dump().find("unmatched"), std::string::npos);
  // The same review on stderr: its error, warning and baseline lines (a run
  // slow enough also prints progress lines, a merge none).
  const auto review_part = [](const std::string& err) {
    std::istringstream in(err);
    std::string kept;
    for (std::string line; std::getline(in, line);)
      if (line.rfind("pdcheck: error:", 0) == 0 || line.rfind("pdcheck: warning:", 0) == 0 ||
          line.rfind("pdcheck: baseline", 0) == 0)
        kept += line + "\n";
    return kept;
  };
  EXPECT_NE(review_part(f.err).find("pdcheck: baseline"), std::string::npos) << f.err;
  EXPECT_EQ(review_part(m.err), review_part(f.err));

  EXPECT_EQ(without_times(read_text(tmp("ci_merged.xml"))),
            without_times(read_text(tmp("ci_full.xml"))));
  EXPECT_EQ(read_json(tmp("ci_merged.sarif")), read_json(tmp("ci_full.sarif")));
  EXPECT_EQ(read_text(tmp("ci_merged_sup.json")), read_text(tmp("ci_full_sup.json")));
  const json page = timeless_page_data(tmp("ci_merged.html"));
  ASSERT_TRUE(page.is_object()) << "no page written by the merge";
  EXPECT_FALSE(page["findings"].empty());
  EXPECT_EQ(page, timeless_page_data(tmp("ci_full.html")));

  // --fail-on new: only g1's finding is new; the bar holds for both.
  for (const char* bar : {"new", "none"}) {
    const std::string flags = ci + " --allow-stale-suppressions --fail-on " + bar;
    EXPECT_EQ(run("merge" + joined(shards) + " -q" + flags, "").code,
              run(s + " -q" + flags, "").code)
        << bar;
  }
  // --fail-on new without a baseline is refused, as for a run.
  const CliResult nb = run("merge" + joined(shards) + " -q --fail-on new", "");
  EXPECT_EQ(nb.code, 2);
  EXPECT_NE(nb.err.find("--fail-on new needs --baseline"), std::string::npos) << nb.err;
  // A bad output path fails before anything is written.
  const CliResult bad = run(
      "merge" + joined(shards) + " -q -o " + tmp("ci_never.json") + " --junit /nonexistent/x.xml",
      "");
  EXPECT_EQ(bad.code, 2);
  EXPECT_FALSE(std::ifstream(tmp("ci_never.json")).good());
}

TEST(Shard, MergeRefusesMissingDuplicatedAndForeignShards) {
  const std::string s = scene("shard_refuse.json");
  const auto shards = run_shards(s, 3, "ref");
  auto merge = [](const std::vector<std::string>& files) {
    return run("merge" + joined(files) + " -q -o " + tmp("refused.json"), "");
  };
  CliResult r = merge({shards[0], shards[2]});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("shard(s) 2 of 3 missing"), std::string::npos) << r.err;
  r = merge({shards[0], shards[1], shards[1], shards[2]});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("shard 2/3 given twice"), std::string::npos) << r.err;
  // Shard 3 of another scene (one part moved).
  const std::string other = scene("shard_other.json", 0.25);
  r = merge({shards[0], shards[1], run_shard(other, 3, 3, "foreign")});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("scene content hash"), std::string::npos) << r.err;
  // Shard 3 under other settings.
  r = merge({shards[0], shards[1], run_shard(s, 3, 3, "tol", "--tolerance 0.2")});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("settings hash"), std::string::npos) << r.err;
  // Shards of another split.
  r = merge({shards[0], run_shard(s, 2, 2, "two"), shards[2]});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("shard count"), std::string::npos) << r.err;
  // A report without a manifest.
  const std::string plain = tmp("plain.json");
  run(s + " -q -o " + plain);
  r = merge({plain});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("not a shard report"), std::string::npos) << r.err;
  // Nothing written on refusal.
  EXPECT_FALSE(std::ifstream(tmp("refused.json")).good());
}

TEST(Shard, ShardArgumentsAreChecked) {
  const std::string s = scene("shard_args.json", 0.0, 5);
  for (const char* bad : {"0/3", "4/3", "1/0", "x/3", "2", "1/3/4", "-1/3"}) {
    const CliResult r = run(s + " -q --shard " + std::string(bad), "");
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_NE(r.err.find("--shard"), std::string::npos) << r.err;
  }
  const CliResult b = run(s + " -q --shard 1/2 --baseline " + s, "");
  EXPECT_EQ(b.code, 2);
  EXPECT_NE(b.err.find("--baseline applies to the whole run"), std::string::npos) << b.err;
}

TEST(Shard, AutoReadsCiAndSlurmVariables) {
  const std::string s = scene("shard_auto.json", 0.0, 5);
  const std::string out = tmp("auto.json");
  // Without the variables: refused, not every shard doing the same work.
  CliResult r = run(s + " -q --shard auto -o " + out, "");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("neither CI_NODE_INDEX/CI_NODE_TOTAL nor SLURM_ARRAY_TASK_ID"),
            std::string::npos)
      << r.err;
  r = run(s + " -q --shard auto -o " + out, "CI_NODE_INDEX=2 CI_NODE_TOTAL=3 ");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(read_json(out)["shard"]["index"], 2);
  EXPECT_EQ(read_json(out)["shard"]["total"], 3);
  r = run(s + " -q --shard auto --shard-total 4 -o " + out,
          "SLURM_ARRAY_TASK_ID=7 SLURM_ARRAY_TASK_MIN=5 ");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(read_json(out)["shard"]["index"], 3);
  EXPECT_EQ(read_json(out)["shard"]["total"], 4);
  r = run(s + " -q --shard auto -o " + out, "SLURM_ARRAY_TASK_ID=1 ");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--shard-total"), std::string::npos) << r.err;
  r = run(s + " -q --shard auto -o " + out, "CI_NODE_INDEX=4 CI_NODE_TOTAL=3 ");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("shard 4 is not in 1..3"), std::string::npos) << r.err;
}

TEST(Shard, EnvironmentRules) {
  auto env = [](std::map<std::string, std::string> vars) {
    return [vars = std::move(vars)](const char* name) -> const char* {
      const auto it = vars.find(name);
      return it == vars.end() ? nullptr : it->second.c_str();
    };
  };
  auto spec = [&](std::map<std::string, std::string> vars, std::optional<int> total = {},
                  std::optional<int> base = {}) {
    const pd::ShardSpec s = pd::shard_from_environment(env(std::move(vars)), total, base);
    return std::to_string(s.index) + "/" + std::to_string(s.total);
  };
  EXPECT_EQ(spec({{"CI_NODE_INDEX", "1"}, {"CI_NODE_TOTAL", "5"}}), "1/5");
  EXPECT_EQ(spec({{"CI_NODE_INDEX", "5"}, {"CI_NODE_TOTAL", "5"}}, 5), "5/5");
  EXPECT_EQ(spec({{"SLURM_ARRAY_TASK_ID", "0"}}, 4), "1/4");     // --array=0-3
  EXPECT_EQ(spec({{"SLURM_ARRAY_TASK_ID", "4"}}, 4, 1), "4/4");  // --array=1-4
  EXPECT_EQ(spec({{"SLURM_ARRAY_TASK_ID", "12"},
                  {"SLURM_ARRAY_TASK_MIN", "10"},
                  {"SLURM_ARRAY_TASK_COUNT", "3"}},
                 3),
            "3/3");
  const std::vector<std::pair<std::map<std::string, std::string>, std::optional<int>>> refused = {
      {{}, 3},
      {{{"CI_NODE_INDEX", "1"}}, {}},
      {{{"CI_NODE_TOTAL", "2"}}, {}},
      {{{"CI_NODE_INDEX", "0"}, {"CI_NODE_TOTAL", "2"}}, {}},  // GitLab counts from 1
      {{{"CI_NODE_INDEX", "1"}, {"CI_NODE_TOTAL", "2"}}, 3},
      {{{"CI_NODE_INDEX", "one"}, {"CI_NODE_TOTAL", "2"}}, {}},
      {{{"SLURM_ARRAY_TASK_ID", "4"}}, 4},  // base 0: 5 of 4
      {{{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_COUNT", "8"}}, 4},
      {{{"SLURM_ARRAY_TASK_ID", "1"}, {"CI_NODE_INDEX", "1"}, {"CI_NODE_TOTAL", "2"}}, 4},
  };
  for (const auto& [vars, total] : refused)
    EXPECT_THROW(pd::shard_from_environment(env(vars), total, std::nullopt), pd::ShardError)
        << json(vars).dump();
}

TEST(Shard, GnuParallelRunsTheShards) {
  if (!have_command("parallel"))
    GTEST_SKIP() << "GNU parallel is not installed (Debian package parallel; scripts/setup.sh "
                    "installs it)";
  const std::string s = scene("shard_parallel.json");
  const std::string full = tmp("par_full.json"), merged = tmp("par_merged.json");
  const CliResult f = run(s + " -q --jobs 1 -o " + full);
  const std::string prefix = tmp("par_");
  // The recipe of docs/scale-out.md.
  const CliResult p = shell(kNoShardEnv + kCrash + "parallel --will-cite --halt now,fail=1 -j 2 " +
                            pd_test::pdcheck_binary_for(kCrash) + " " + s +
                            " --jobs 1 -q --shard {}/4 -o " + prefix + "{}.json ::: 1 2 3 4");
  ASSERT_EQ(p.code, 0) << p.err;
  const CliResult m =
      run("merge" +
              joined({prefix + "1.json", prefix + "2.json", prefix + "3.json", prefix + "4.json"}) +
              " -o " + merged,
          "");
  EXPECT_EQ(m.code, f.code) << m.err;
  expect_same_report(read_json(merged), read_json(full), "GNU parallel's 4 shards merged");
}

TEST(Reuse, MovingOnePartResolvesExactlyItsPairs) {
  const std::string before = scene("reuse_before.json"), after = scene("reuse_after.json", 0.25);
  const std::string old = tmp("reuse_old.json"), full = tmp("reuse_full.json"),
                    again = tmp("reuse_again.json");
  ASSERT_EQ(run(before + " -q --jobs 2 -o " + old).code, 3);
  const CliResult f = run(after + " -q --jobs 2 -o " + full);
  const CliResult r = run(after + " --jobs 2 --reuse " + old + " -o " + again);
  EXPECT_EQ(r.code, f.code) << r.err;
  json got = read_json(again);
  long reused = 0, moved = 0;
  for (auto& p : got["pairs"]) {
    const bool involves = p["a"] == "g2a" || p["b"] == "g2a";
    const bool was_reused = p.value("reused", false);
    moved += involves;
    reused += was_reused;
    if (involves || p["status"] == "error")  // errors are always tried again
      EXPECT_FALSE(was_reused) << p.dump();
    else
      EXPECT_TRUE(was_reused) << p.dump();
    p.erase("reused");
  }
  EXPECT_GT(moved, 0);
  EXPECT_GT(reused, 0);
  EXPECT_NE(r.err.find(std::to_string(reused) + " pair(s) reused"), std::string::npos) << r.err;
  // The summary says how many were reused and why the rest were solved: the
  // moved part's pairs and the error, as the pairs show.
  const json counts = got["summary"]["reuse"];
  EXPECT_EQ(counts["reused"], reused) << counts;
  EXPECT_EQ(counts["solved"]["part_changed"], moved) << counts;
  long solved = 0;
  for (const auto& [why, n] : counts["solved"].items()) solved += n.get<long>();
  EXPECT_EQ(reused + solved, got["summary"]["candidate_pairs"].get<long>()) << counts;
  EXPECT_NE(r.err.find(std::to_string(moved) + " with a changed or new part"), std::string::npos)
      << r.err;
  got["summary"].erase("reuse");
  expect_same_report(got, read_json(full), "--reuse after moving g2a");
  // Other settings: nothing stands.
  const CliResult t = run(after + " -q --tolerance 0.2 --reuse " + old + " -o " + again);
  const json again_report = read_json(again);  // range-for over a temporary's member dangles
  for (const auto& p : again_report["pairs"]) EXPECT_FALSE(p.value("reused", false)) << p.dump();
  EXPECT_EQ(again_report["summary"]["reuse"],
            json({{"reused", 0},
                  {"solved", {{"settings", again_report["summary"]["candidate_pairs"]}}}}));
  // Shards reuse too, and still merge into the full run's report.
  const auto shards = run_shards(after, 3, "reuse", "--reuse " + old);
  const std::string merged = tmp("reuse_merged.json");
  EXPECT_EQ(run("merge" + joined(shards) + " -o " + merged, "").code, f.code);
  json m = read_json(merged);
  for (auto& p : m["pairs"]) p.erase("reused");
  EXPECT_EQ(m["summary"]["reuse"], counts) << "the shards' counts, summed";
  m["summary"].erase("reuse");
  expect_same_report(m, read_json(full), "3 shards with --reuse");
  // A report without content hashes cannot be reused from.
  json stripped = read_json(old);
  stripped.erase("hashes");
  const std::string bad = write_temp("reuse_nohash.json", stripped.dump());
  const CliResult b = run(after + " -q --reuse " + bad);
  EXPECT_EQ(b.code, 2);
  EXPECT_NE(b.err.find("$.hashes: missing"), std::string::npos) << b.err;
}
