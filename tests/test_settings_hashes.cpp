// Every solver setting feeds every hash of the settings (solve/settings.h's
// for_each_setting): the settings hash (--reuse, shards) and the refinement
// cache key. A setting added to SolverSettings and listed in for_each_setting
// is changed and checked here with no edit of this file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "batch/content_hashes.h"
#include "batch/refine_cache.h"
#include "batch/run.h"
#include "report/report_json.h"

using namespace pd;

namespace {

// Changes the `target`-th setting (in for_each_setting's order) by the least
// it can: another method, the next integer, the next double up.
struct ChangeOne {
  int target;
  int k = 0;
  bool hit(const Setting&) { return k++ == target; }
  void operator()(const Setting& s, Method& m) {
    if (hit(s)) m = m == Method::kMlsl ? Method::kExact : Method::kMlsl;
  }
  void operator()(const Setting& s, std::uint64_t& v) {
    if (hit(s)) ++v;
  }
  void operator()(const Setting& s, int& v) {
    if (hit(s)) ++v;
  }
  void operator()(const Setting& s, double& v) {
    if (hit(s)) v = std::nextafter(v, std::numeric_limits<double>::infinity());
  }
};

int setting_count() {
  int n = 0;
  const SolverSettings s;
  for_each_setting(s, [&](const Setting&, const auto&) { ++n; });
  return n;
}

Part part_at(double dx) {
  Part p;
  p.id = "p" + std::to_string(dx);
  p.mode = Pieces::kAuto;
  p.convex = false;
  Points v(3, 4);
  v << 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1;
  v.row(0).array() += dx;
  Hull h;
  h.vertices = v;
  p.pieces = {h};
  return p;
}

std::string key_of(const SolverSettings& s) {
  PairResult hull;
  hull.status = Status::kInterference;
  hull.depth = 0.5;
  RunOptions o;
  o.tolerance = 0.05;
  o.solver = s;
  return refinement_key(part_at(0.0), part_at(0.5), hull, o, {});
}

}  // namespace

TEST(SettingsHashes, EverySettingChangesEveryHash) {
  const SolverSettings base;
  const std::string settings = settings_hash(base, 0.1, {}), key = key_of(base);
  EXPECT_EQ(setting_count(), 15);
  for (int k = 0; k < setting_count(); ++k) {
    SolverSettings s = base;
    ChangeOne change{k};
    for_each_setting(s, change);
    std::string name;
    int n = 0;
    for_each_setting(s, [&](const Setting& setting, const auto&) {
      if (n++ == k) name = setting.key;
    });
    SCOPED_TRACE(name);
    EXPECT_NE(settings_hash(s, 0.1, {}), settings) << "the settings hash";
    EXPECT_NE(key_of(s), key) << "the refinement cache key";
  }
}

// Seeds that differ above 2^53 (where doubles cannot tell them apart).
TEST(SettingsHashes, SeedsBeyondTwoToThe53AreDifferentSettings) {
  SolverSettings a, b;
  a.seed = (std::uint64_t{1} << 60);
  b.seed = a.seed + 1;
  ASSERT_EQ(static_cast<double>(a.seed), static_cast<double>(b.seed));
  EXPECT_NE(settings_hash(a, 0.1, {}), settings_hash(b, 0.1, {}));
  EXPECT_NE(key_of(a), key_of(b));
}

// The report's "method" block shows each method's own settings, in the
// documented order (docs/report-format.md).
TEST(SettingsHashes, TheReportShowsEachMethodsSettings) {
  const std::vector<std::pair<Method, std::vector<std::string>>> expected = {
      {Method::kMlsl, {"name", "seed", "samples", "reduced", "sigma", "tau", "link_scale"}},
      {Method::kMlslPaper, {"name", "seed", "N", "M", "sigma", "tau"}},
      {Method::kGrid, {"name", "seed", "grid"}},
      {Method::kGsLocal, {"name", "seed", "gs_local"}},
      {Method::kExact, {"name", "seed"}}};
  for (const auto& [m, keys] : expected) {
    ReportContext ctx;
    ctx.solver.method = m;
    ctx.solver.seed = std::uint64_t{1} << 60;
    const auto doc = report_json(ctx, RunResult{});
    std::vector<std::string> got;
    for (const auto& item : doc["method"].items()) got.push_back(item.key());
    EXPECT_EQ(got, keys) << method_name(m);
    EXPECT_EQ(doc["method"]["name"], method_name(m));
    EXPECT_EQ(doc["method"]["seed"].get<std::uint64_t>(), ctx.solver.seed);
  }
}
