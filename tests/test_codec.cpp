// The one codec of a pair result (results/codec.h) on every path a result
// takes: worker message -> report -> merge -> --reuse -> refinement cache.
//
// Adding a field to PairResult is one edit: declare it, and describe it in
// for_each_field (results/pair_fields.h). This test needs none: it fills,
// lists and compares the fields by walking that same description, so the new
// field is set to a non-default value and checked on every path below. (A
// member left out of the description is in no encoding at all: the
// description is the list to extend.)
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

#include "awkward_doubles.h"
#include "batch/refine_cache.h"
#include "batch/reuse.h"
#include "report/merge.h"
#include "report/prior_report.h"
#include "report/report_json.h"
#include "results/codec.h"
#include "results/pair_fields.h"
#include "results/part_fields.h"
#include "scratch_dir.h"

namespace {

using pd::Field;
using pd::PairResult;
using pd::Status;
using pd::Vec3;
using Fields = std::vector<std::pair<std::string, std::string>>;
namespace fs = std::filesystem;

// Sets every field it visits to a value unlike its default and unlike the
// other fields' (the k-th number).
struct Fill {
  int k = 0;
  void operator()(const Field&, double& v) { v = 0.25 + ++k; }
  void operator()(const Field&, int& v) { v = 10 + ++k; }
  void operator()(const Field&, long& v) { v = 100000 + ++k; }
  void operator()(const Field&, bool& v) { v = !v; }
  void operator()(const Field&, std::string& v) { v = "text " + std::to_string(++k); }
  void operator()(const Field&, std::vector<std::string>& v) {
    v = {"first " + std::to_string(++k), "second"};
  }
  void operator()(const Field&, std::vector<std::pair<double, double>>& v) {
    v = {{0.5, -0.125}, {1.5, 0.25 + ++k}};
  }
  void operator()(const Field&, Vec3& v) { v = Vec3(0.6, -0.75 - ++k, 0.8); }
  void operator()(const Field&, Status& s) { s = Status::kInterference; }
  void operator()(const Field&, pd::StopReason& s) { s = pd::StopReason::kCap; }
  template <class T>
  void operator()(const Field& f, std::array<T, 2>& v) {
    (*this)(f, v[0]);
    (*this)(f, v[1]);
  }
  template <class T>
  void operator()(const Field& f, std::optional<T>& v) {
    T x{};
    (*this)(f, x);
    v = x;
  }
  void operator()(const Field&, pd::ExactVerdict& v) { v = pd::ExactVerdict::kFalsePositive; }
  void operator()(const Field&, pd::ExactBasis& b) { b = pd::ExactBasis::kSolids; }
  void operator()(const Field&, pd::SolveStats& s) { for_each_field(s, *this); }
  void operator()(const Field&, pd::MotionTrace& m) { for_each_field(m, *this); }
  void operator()(const Field&, pd::ExactCheck& e) { for_each_field(e, *this); }
};

std::string bits(double x) {
  std::uint64_t u;
  std::memcpy(&u, &x, sizeof u);
  std::ostringstream s;
  s << std::setprecision(17) << x << " (0x" << std::hex << u << ")";
  return s.str();
}

// Lists every field as (key, value text), doubles bit for bit; `report`: only
// those the report shows (for this result: conditions are on its fields).
struct List {
  Fields* out;
  bool report;
  std::string prefix;

  template <class T>
  void operator()(const Field& f, const T& v) const {
    if (f.echo || (report && !f.shown)) return;
    add(prefix + (f.group ? std::string(f.group) + "." : "") + f.key, v);
  }
  void add(const std::string& key, double v) const { out->emplace_back(key, bits(v)); }
  void add(const std::string& key, int v) const { out->emplace_back(key, std::to_string(v)); }
  void add(const std::string& key, long v) const { out->emplace_back(key, std::to_string(v)); }
  void add(const std::string& key, bool v) const { out->emplace_back(key, v ? "true" : "false"); }
  void add(const std::string& key, const std::string& v) const { out->emplace_back(key, v); }
  void add(const std::string& key, const std::vector<std::string>& v) const {
    for (size_t k = 0; k < v.size(); ++k) add(key + "[" + std::to_string(k) + "]", v[k]);
    out->emplace_back(key + ".size", std::to_string(v.size()));
  }
  void add(const std::string& key, const std::vector<std::pair<double, double>>& v) const {
    for (size_t k = 0; k < v.size(); ++k) {
      add(key + "[" + std::to_string(k) + "].t", v[k].first);
      add(key + "[" + std::to_string(k) + "].s", v[k].second);
    }
    out->emplace_back(key + ".size", std::to_string(v.size()));
  }
  void add(const std::string& key, const Vec3& v) const {
    for (int c = 0; c < 3; ++c) add(key + "[" + std::to_string(c) + "]", v[c]);
  }
  void add(const std::string& key, Status s) const { add(key, int(s)); }
  void add(const std::string& key, pd::StopReason s) const { add(key, int(s)); }
  void add(const std::string& key, pd::ExactVerdict v) const { add(key, int(v)); }
  void add(const std::string& key, pd::ExactBasis b) const { add(key, int(b)); }
  template <class T>
  void add(const std::string& key, const std::array<T, 2>& v) const {
    add(key + "[0]", v[0]);
    add(key + "[1]", v[1]);
  }
  template <class T>
  void add(const std::string& key, const std::optional<T>& v) const {
    if (v)
      add(key, *v);
    else
      out->emplace_back(key, "(unset)");
  }
  void add(const std::string& key, const pd::SolveStats& s) const {
    for_each_field(s, List{out, report, key + "."});
  }
  void add(const std::string& key, const pd::MotionTrace& m) const {
    for_each_field(m, List{out, report, key + "."});
  }
  void add(const std::string& key, const pd::ExactCheck& e) const {
    for_each_field(e, List{out, report, key + "."});
  }
};

Fields fields(const PairResult& r, bool report) {
  Fields out;
  for_each_field(r, List{&out, report, ""});
  return out;
}

PairResult filled(Status status) {
  PairResult r;
  r.a = 0;
  r.b = 1;
  for_each_field(r, Fill{});
  r.status = status;
  return r;
}

// A run of the two parts A and B whose one pair is `r`, as a shard 1/1 (so
// that merge reads it) with content hashes (so that --reuse does).
pd::RunResult run_of(const PairResult& r) {
  pd::RunResult run;
  for (const char* id : {"A", "B"}) {
    pd::Part p;
    p.id = id;
    p.source = std::string(id) + ".stl";
    run.parts.push_back(p);
  }
  run.pairs = {r};
  run.all_pairs = 1;
  run.simulated = {"interference"};
  run.part_hashes = {"hash-a", "hash-b"};
  run.scene_hash = "scene-hash";
  run.settings_hash = "settings-hash";
  pd::ShardManifest m;
  m.parts_total = 2;
  m.pairs_total = m.pairs_planned = m.pairs_checked = 1;
  m.part_index = m.owned = {0, 1};
  run.shard = m;
  return run;
}

// The result after each path, in order: the worker message, the report
// merged, the report reused, the refinement cache.
std::vector<std::pair<std::string, PairResult>> every_path(const PairResult& r) {
  std::vector<std::pair<std::string, PairResult>> out;
  const PairResult worker = pd::decode_pair_result(pd::encode_pair_result(r));
  out.emplace_back("worker message", worker);

  pd::ReportContext ctx;
  ctx.scene_path = "scene.json";
  ctx.units = "mm";
  ctx.tolerance = 0.1;
  const auto doc = nlohmann::ordered_json::parse(pd::report_json(ctx, run_of(worker)).dump(2));
  const pd::Merged merged = pd::merge_shard_reports({{"shard.json", doc}});
  out.emplace_back("report, merge", merged.run.pairs.at(0));

  const fs::path dir = pd_test::scratch_dir("codec", "reuse");
  pd::RunResult again = run_of(merged.run.pairs.at(0));
  std::ofstream(dir / "old.json") << pd::report_json(ctx, again).dump(2);
  const pd::PriorResults prior = pd::load_prior_report((dir / "old.json").string());
  const auto reused = pd::prior_result(prior, "settings-hash", 0, "A", "hash-a", 1, "B", "hash-b");
  if (reused) out.emplace_back("report, merge, reuse", *reused);

  const PairResult& last = reused ? *reused : merged.run.pairs.at(0);
  EXPECT_EQ(pd::write_cached_refinement(dir.string(), "key", {last, true}), "");
  const auto cached = pd::read_cached_refinement(dir.string(), "key");
  if (cached) out.emplace_back("..., refinement cache", cached->result);
  fs::remove_all(dir);
  return out;
}

}  // namespace

// Every field the description lists is filled with a value unlike its default
// (so that the paths below could lose it visibly).
TEST(ResultsCodec, EveryFieldIsFilledUnlikeItsDefault) {
  std::map<std::string, std::string> none;
  for (const auto& [key, value] : fields(PairResult{}, false)) none[key] = value;
  const Fields all = fields(filled(Status::kInterference), false);
  EXPECT_GT(all.size(), 40u);
  for (const auto& [key, value] : all) EXPECT_NE(none[key], value) << key;
}

// A decided pair: every field the report shows survives every path, bit for
// bit; the complete encoding (worker, cache) keeps every field.
TEST(ResultsCodec, ADecidedPairSurvivesEveryPath) {
  PairResult r = filled(Status::kInterference);
  r.reused = true;  // what --reuse sets: the paths after it keep it
  const auto paths = every_path(r);
  ASSERT_EQ(paths.size(), 4u);
  EXPECT_EQ(fields(paths[0].second, false), fields(r, false)) << "worker message";
  for (const auto& [path, back] : paths) EXPECT_EQ(fields(back, true), fields(r, true)) << path;
  // Only what the report leaves out (mlsl_iterations, the error of a decided
  // pair) differs after the report.
  const Fields all = fields(r, false), shown = fields(r, true);
  EXPECT_LT(shown.size(), all.size());
  const PairResult cached_alone = pd::decode_pair_result(pd::encode_pair_result(paths[3].second));
  EXPECT_EQ(fields(cached_alone, false), fields(paths[3].second, false));
}

// An error pair: the report gives its error alone, and the error survives.
TEST(ResultsCodec, AnErrorPairKeepsItsErrorThroughReportAndMerge) {
  const PairResult r = filled(Status::kError);
  const auto paths = every_path(r);
  ASSERT_GE(paths.size(), 2u);  // --reuse takes no error pair: it is solved again
  EXPECT_EQ(fields(paths[0].second, false), fields(r, false));
  EXPECT_EQ(fields(paths[1].second, true), fields(r, true));
  const auto j = pd::pair_to_report(r, "A", "B");
  EXPECT_TRUE(j.contains("error"));
  for (const char* key : {"depth", "direction", "margin", "depth_source", "clearance", "motion"})
    EXPECT_FALSE(j.contains(key)) << key;
}

// The report's layout: keys in the documented order, the optional ones left
// out when empty (docs/report-format.md), no −0 in a direction.
TEST(ResultsCodec, TheReportEntryKeepsItsLayout) {
  PairResult r = filled(Status::kInterference);
  r.direction = Vec3(-0.0, 0.6, 0.8);
  const auto j = pd::pair_to_report(r, "A", "B");
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"a",
                                            "b",
                                            "fingerprint",
                                            "status",
                                            "tolerance",
                                            "tolerance_source",
                                            "tolerance_basis",
                                            "tests",
                                            "expected",
                                            "depth",
                                            "direction",
                                            "margin",
                                            "distance",
                                            "depth_source",
                                            "hull_depth",
                                            "depth_bounds",
                                            "confirmed",
                                            "pieces",
                                            "at",
                                            "reason",
                                            "clearance",
                                            "motion",
                                            "exact",
                                            "method",
                                            "fallback",
                                            "warnings",
                                            "stats",
                                            "time_ms",
                                            "reused"}));
  EXPECT_EQ(j["direction"].dump(), "[0.0,0.6,0.8]");
  EXPECT_EQ(j["clearance"]["distance"], j["distance"]);  // repeated for the clearance check
  EXPECT_FALSE(j["stats"].contains("mlsl_iterations"));
  const auto plain = pd::pair_to_report(filled(Status::kSeparated), "A", "B");
  PairResult bare;
  bare.a = 0, bare.b = 1, bare.status = Status::kSeparated;
  std::vector<std::string> bare_keys;
  const auto bare_entry = pd::pair_to_report(bare, "A", "B");
  for (const auto& item : bare_entry.items()) bare_keys.push_back(item.key());
  EXPECT_EQ(bare_keys,
            (std::vector<std::string>{"a", "b", "fingerprint", "status", "depth", "direction",
                                      "margin", "depth_source", "method", "stats", "time_ms"}));
  EXPECT_TRUE(plain.contains("reason"));
}

// A part entry: every field described in results/part_fields.h is filled
// unlike its default and read back as written (the merge and --reuse read
// parts through part_from_report), in the report's key order.
TEST(ResultsCodec, APartSurvivesTheReportAndItsReaders) {
  const auto listed = [](const pd::PartResult& p) {
    Fields out;
    for_each_field(p, List{&out, true, ""});
    return out;
  };
  pd::PartResult p;
  for_each_field(p, Fill{});
  std::map<std::string, std::string> none;
  for (const auto& [key, value] : listed(pd::PartResult{})) none[key] = value;
  for (const auto& [key, value] : listed(p)) EXPECT_NE(none[key], value) << key;
  const nlohmann::ordered_json j = pd::part_to_report(p);
  EXPECT_EQ(listed(pd::part_from_report(j)), listed(p));
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  EXPECT_EQ(keys,
            (std::vector<std::string>{"id", "source", "vertices", "hull_vertices", "pieces",
                                      "warnings", "resolution", "box", "content_hash", "convex",
                                      "sag", "tessellation", "decomposition_seconds", "cached",
                                      "decomposition_note", "tags", "group", "sets", "error"}));
  EXPECT_EQ(j["box"].size(), 2u);
  EXPECT_EQ(j["sag"].size(), 3u);
}

// The worker message alone, at the edges of double precision (issue 11).
TEST(PairResultCodec, KeepsEveryDoubleBitForBit) {
  for (const double x : pd_test::kAwkward) {
    const PairResult r =
        pd::decode_pair_result(pd::encode_pair_result(pd_test::with_every_double(x)));
    SCOPED_TRACE(x);
    EXPECT_EQ(r.a, 3);
    EXPECT_EQ(r.b, 7);
    EXPECT_EQ(r.status, pd::Status::kInterference);
    EXPECT_EQ(pd_test::raw_bits(r.depth), pd_test::raw_bits(x));
    EXPECT_EQ(pd_test::raw_bits(r.direction.x()), pd_test::raw_bits(x));
    EXPECT_EQ(pd_test::raw_bits(r.direction.y()), pd_test::raw_bits(-x));
    EXPECT_EQ(pd_test::raw_bits(r.direction.z()), pd_test::raw_bits(0.5));
    ASSERT_TRUE(r.distance);
    EXPECT_EQ(pd_test::raw_bits(*r.distance), pd_test::raw_bits(x));
    EXPECT_EQ(pd_test::raw_bits(r.margin), pd_test::raw_bits(x));
    EXPECT_EQ(pd_test::raw_bits(r.time_ms), pd_test::raw_bits(x));
    ASSERT_TRUE(r.clearance_min);
    EXPECT_EQ(pd_test::raw_bits(*r.clearance_min), pd_test::raw_bits(x));
    ASSERT_TRUE(r.motion);
    EXPECT_EQ(r.motion->steps, 5);
    EXPECT_EQ(pd_test::raw_bits(r.motion->max_depth), pd_test::raw_bits(x));
    EXPECT_EQ(pd_test::raw_bits(r.motion->t_max_depth), pd_test::raw_bits(x));
    ASSERT_TRUE(r.motion->min_distance);
    EXPECT_EQ(pd_test::raw_bits(*r.motion->min_distance), pd_test::raw_bits(x));
    EXPECT_EQ(pd_test::raw_bits(r.motion->t_min_distance), pd_test::raw_bits(x));
    ASSERT_EQ(r.motion->series.size(), 2u);
    EXPECT_EQ(pd_test::raw_bits(r.motion->series[0].first), pd_test::raw_bits(x));
    EXPECT_EQ(pd_test::raw_bits(r.motion->series[1].second), pd_test::raw_bits(x));
    EXPECT_EQ(r.warnings, (std::vector<std::string>{"first", "second"}));
  }
}

TEST(PairResultCodec, RefusesDamagedPayloadsWithAnException) {
  const std::string good = pd::encode_pair_result(pd_test::with_every_double(1.0));
  EXPECT_NO_THROW(pd::decode_pair_result(good));
  EXPECT_ANY_THROW(pd::decode_pair_result(""));
  EXPECT_ANY_THROW(pd::decode_pair_result("{\"a\": 1}"));
  EXPECT_ANY_THROW(pd::decode_pair_result(good.substr(0, good.size() / 2)));
  // A status outside the enum is not cast into one.
  PairResult bad = pd_test::with_every_double(1.0);
  bad.status = static_cast<pd::Status>(99);
  EXPECT_ANY_THROW(pd::decode_pair_result(pd::encode_pair_result(bad)));
}
