// pdcheck on B-rep parts nobody shaped for it: Open CASCADE's sample
// mechanism (Debian's occt-misc: a nut, a screw and a rod), each pair's
// status and exact verdict against a reference from Open CASCADE alone (the
// solids' distance and their common volume, tests/brep_cases.h). Skipped
// when occt-misc is not installed.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "brep_cases.h"
#include "cli_support.h"

namespace {

const std::string kDir = "/usr/share/opencascade/data/occ/";

TEST(RealBrepFiles, OpenCascadeSampleMechanismAgreesWithItsOwnBooleans) {
  const std::map<std::string, std::string> files = {
      {"nut", "mal_ecrou.brep"}, {"screw", "mal_vis.brep"}, {"rod", "mal_tige.brep"}};
  for (const auto& [id, file] : files)
    if (!std::filesystem::exists(kDir + file))
      GTEST_SKIP() << "Open CASCADE's sample parts are not installed (Debian occt-misc)";
  const double tolerance = 0.1;
  std::string scene = R"({"tolerance": 0.1, "units": "mm", "parts": [)";
  for (const auto& [id, file] : files)
    scene += std::string(scene.back() == '[' ? "" : ",") + R"({"id": ")" + id + R"(", "mesh": ")" +
             kDir + file + "\"}";
  scene += "]}";
  const pd::test::CliResult r =
      pd::test::pdcheck(pd::test::write_temp("occ_sample.json", scene) + " --quiet --no-cache");
  ASSERT_TRUE(r.code == 0 || r.code == 1) << r.err;
  const nlohmann::json rep = nlohmann::json::parse(r.out);
  EXPECT_EQ(rep["summary"]["part_errors"], 0);
  std::map<std::pair<std::string, std::string>, nlohmann::json> pairs;
  for (const auto& p : rep["pairs"]) {
    std::string a = p["a"], b = p["b"];
    if (a > b) std::swap(a, b);
    pairs[{a, b}] = p;
  }
  for (auto i = files.begin(); i != files.end(); ++i)
    for (auto j = std::next(i); j != files.end(); ++j) {
      const auto [a, b] = std::minmax(i->first, j->first);
      const pd_test::ExactReference ref =
          pd_test::exact_reference(kDir + files.at(a), kDir + files.at(b));
      const std::string what = a + "/" + b;
      const auto found = pairs.find({a, b});
      if (ref.distance > 1e-6) {  // apart: culled, or separated
        if (found != pairs.end()) {
          EXPECT_EQ(found->second["status"], "separated") << what;
        }
        continue;
      }
      ASSERT_NE(found, pairs.end()) << what << " touches or overlaps and was culled";
      const nlohmann::json& p = found->second;
      ASSERT_TRUE(p.contains("exact")) << what;
      if (ref.common_volume < 1e-6) {  // touching: separated on the solids
        EXPECT_EQ(p["status"], "separated") << what;
        // Found touching on the solids, or certified within the tolerance by
        // the deflection bound (which claims no overlap: its bracket starts at 0).
        if (p["exact"]["verdict"] == "false_positive") {
          EXPECT_EQ(p["exact"]["by"], "deflection-bound") << what;
          EXPECT_EQ(p["exact"]["depth_bounds"][0], 0.0) << what;
          EXPECT_LE(p["exact"]["depth_bounds"][1].get<double>(), tolerance) << what;
        } else {
          EXPECT_EQ(p["exact"]["verdict"], "touching") << what;
        }
      } else {  // overlapping by a volume: the depth bracket is above zero
        const double lo = p["exact"]["depth_bounds"][0], hi = p["exact"]["depth_bounds"][1];
        EXPECT_GT(hi, 0.0) << what;
        EXPECT_EQ(p["status"], lo > tolerance ? "interference" : "false_positive") << what;
        EXPECT_NE(p["exact"]["verdict"], "inconsistent") << what;
        // The thickness (twice the largest ball inside both) is at most the
        // common part's narrowest box extent: the bracket's lower end too.
        EXPECT_LE(lo, ref.common_min_extent * (1 + 1e-9)) << what;
      }
    }
  // Sanity of the reference itself: the nut sits on the screw's thread.
  EXPECT_GT(
      pd_test::exact_reference(kDir + files.at("nut"), kDir + files.at("screw")).common_volume,
      1.0);
}

}  // namespace
