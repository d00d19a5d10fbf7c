// The merge of shard reports in-process (report/merge.h): the shards of one run,
// given in any order, make the unsharded run's report pair for pair with its
// counts; a missing or repeated shard is refused naming the files.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "batch/run.h"
#include "cube_json.h"
#include "report/merge.h"
#include "report/report_json.h"
#include "report/writer.h"
#include "scene/scene.h"

using namespace pd;
using nlohmann::json;

using pd_test::cube_json;

namespace {

// Groups 10 apart along x, each a pair of unit cubes: interfering (0.5 in),
// within the tolerance (0.05 in), touching, 0.5 apart (checked, separated) and
// 3 apart (culled); a chain of three in the first group.
SceneSpec scene() {
  const double offsets[] = {0.5, 0.95, 1.0, 1.5, 4.0};
  json parts = json::array();
  for (int g = 0; g < 10; ++g) {
    const std::string id = "g" + std::to_string(g);
    parts.push_back(cube_json(id + "a", 10.0 * g, 0, 0, 1));
    parts.push_back(cube_json(id + "b", 10.0 * g + offsets[g % 5], 0.2, 0, 1));
  }
  parts.push_back(cube_json("chain", 0.7, 0.5, 0, 1));
  const json s = {{"tolerance", 0.1}, {"units", "mm"}, {"parts", parts}};
  return parse_scene_json(s.dump(), "merge.json", ".");
}

RunResult run(const SceneSpec& spec, std::optional<ShardSpec> shard) {
  RunOptions o;
  o.tolerance = *spec.tolerance;
  o.quiet = true;
  spec.solver.apply(o.solver);
  o.shard = shard;
  return run_scene(spec, o);
}

ReportContext context(const SceneSpec& spec) {
  ReportContext ctx;
  ctx.scene_path = "merge.json";
  ctx.units = "mm";
  ctx.tolerance = *spec.tolerance;
  spec.solver.apply(ctx.solver);
  return ctx;
}

ShardReport shard_report(const SceneSpec& spec, int k, int n) {
  const RunResult r = run(spec, ShardSpec{k, n});
  return {"shard" + std::to_string(k) + ".json",
          nlohmann::ordered_json::parse(report_json(context(spec), r).dump())};
}

// The report as a run writes it (with its review: finding groups, exit code).
json run_report(const SceneSpec& spec, const RunResult& r) {
  const ReportContext ctx = context(spec);
  ReviewOptions options;
  options.tolerance = ctx.tolerance;
  options.units = ctx.units;
  const Review review = review_run(r, options, summarize(r).incomplete());
  return json::parse(report_document({ctx, r, review, options}).dump());
}

// The report without what depends on the clock.
json timeless(json d) {
  d.erase("seconds");
  d.erase("stage_seconds");
  for (auto& p : d["pairs"]) p.erase("time_ms");
  return d;
}

}  // namespace

TEST(Merge, ShardsInAnyOrderMakeTheUnshardedRunsPairsAndCounts) {
  const SceneSpec spec = scene();
  const RunResult whole = run(spec, std::nullopt);
  const json want = timeless(run_report(spec, whole));
  // The scene has what the merge must get right.
  for (const char* k : {"separated", "false_positive", "interference", "culled"})
    ASSERT_GT(want["summary"][k].get<long>(), 0) << k << ": " << want["summary"].dump();
  for (int n : {2, 3}) {
    SCOPED_TRACE(std::to_string(n) + " shards");
    std::vector<ShardReport> shards;
    for (int k = n; k >= 1; --k) shards.push_back(shard_report(spec, k, n));  // reversed
    const Merged m = merge_shard_reports(shards);
    const json got = timeless(json::parse(m.doc.dump()));
    EXPECT_EQ(got["pairs"], want["pairs"]);
    EXPECT_EQ(got["parts"], want["parts"]);
    EXPECT_EQ(got["groups"], want["groups"]);
    for (const auto& [key, value] : want["summary"].items())
      EXPECT_EQ(got["summary"][key], value) << "summary." << key;
    for (const auto& [key, value] : want.items()) EXPECT_EQ(got[key], value) << key;
    EXPECT_EQ(got.size(), want.size());
    EXPECT_EQ(m.run.pairs.size(), whole.pairs.size());
    EXPECT_EQ(m.run.parts.size(), whole.parts.size());
    EXPECT_NE(m.summary_line.find("interference"), std::string::npos) << m.summary_line;
  }
}

TEST(Merge, AMissingOrRepeatedShardIsRefusedNamingTheFiles) {
  const SceneSpec spec = scene();
  const ShardReport one = shard_report(spec, 1, 3), two = shard_report(spec, 2, 3);
  try {
    merge_shard_reports({one, two});
    ADD_FAILURE() << "merged 2 of 3 shards";
  } catch (const MergeError& e) {
    EXPECT_NE(std::string(e.what()).find("shard(s) 3 of 3 missing"), std::string::npos) << e.what();
  }
  ShardReport again = one;
  again.path = "copy.json";
  try {
    merge_shard_reports({one, again, two});
    ADD_FAILURE() << "merged a repeated shard";
  } catch (const MergeError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("shard 1/3 given twice: shard1.json and copy.json"), std::string::npos)
        << what;
  }
}
