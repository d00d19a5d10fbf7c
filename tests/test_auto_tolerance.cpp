// tolerance auto (issue 27): the scene's forms, the sag in the hull cache, each pair's band
// from its parts' sags where they meet, and what a finding says about it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "batch/pair_tolerance.h"
#include "cli_support.h"
#include "corpus/cad_shapes.h"
#include "page_data.h"
#include "report/finding_text.h"
#include "sag_part.h"
#include "scene/hull_cache.h"
#include "scene/scene.h"
#include "tolerances.h"

using namespace pd;
using pd_test::chord_sag;
using pd_test::sag_part;
using namespace pd::test;

namespace {

SceneSpec parse(const std::string& tolerance, const std::string& part_extra = "") {
  return parse_scene_json(
      R"({"tolerance": )" + tolerance +
          R"(, "parts": [{"id": "a", "vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]])" + part_extra +
          "}]}",
      "s.json", "");
}

std::string error_of(const std::string& tolerance, const std::string& part_extra = "") {
  try {
    parse(tolerance, part_extra);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(AutoTolerance, SceneForms) {
  const SceneSpec fixed = parse("0.1");
  EXPECT_FALSE(fixed.auto_tolerance);
  EXPECT_EQ(*fixed.tolerance, 0.1);
  const SceneSpec a = parse(R"("auto")");
  ASSERT_TRUE(a.auto_tolerance);
  EXPECT_FALSE(a.auto_tolerance->min);
  const SceneSpec clamped = parse(R"({"auto": true, "min": 0.01, "max": 0.2})", R"(, "sag": 0.02)");
  ASSERT_TRUE(clamped.auto_tolerance);
  EXPECT_EQ(*clamped.auto_tolerance->min, 0.01);
  EXPECT_EQ(*clamped.auto_tolerance->max, 0.2);
  EXPECT_EQ(*clamped.tolerance, 0.01);  // the nominal one
  EXPECT_EQ(*clamped.parts[0].sag, 0.02);
  // A part's sag is in its units.
  const SceneSpec inches = parse(R"("auto")", R"(, "units": "in", "sag": 0.001)");
  EXPECT_NEAR(*inches.parts[0].sag, 0.0254, 1e-15);
}

TEST(AutoTolerance, BadFormsNameTheField) {
  EXPECT_NE(error_of(R"("automatic")").find("s.json: tolerance: expected a number > 0, \"auto\""),
            std::string::npos);
  EXPECT_NE(error_of(R"({"auto": false})").find("tolerance.auto: expected true"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"auto": true, "mni": 1})").find("tolerance.mni: unknown key"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"auto": true, "min": 0.2, "max": 0.1})").find("tolerance.max: must be >="),
            std::string::npos);
  EXPECT_NE(error_of(R"({"auto": true, "min": -1})").find("tolerance.min: must be > 0"),
            std::string::npos);
  EXPECT_NE(error_of(R"("auto")", R"(, "sag": -0.1)").find("parts[0].sag: must be >= 0"),
            std::string::npos);
}

TEST(AutoTolerance, BandIsSagsAndStepsWithTheMarginClamped) {
  const double m = 1 + tol::kAutoToleranceMargin;
  EXPECT_DOUBLE_EQ(AutoTolerance{}.band(0.1, 0.02, 0.001, 0.002), 0.123 * m);
  EXPECT_DOUBLE_EQ((AutoTolerance{0.5, std::nullopt}.band(0.1, 0, 0, 0)), 0.5);
  EXPECT_DOUBLE_EQ((AutoTolerance{std::nullopt, 0.05}.band(0.1, 0, 0, 0)), 0.05);
}

TEST(AutoTolerance, CacheRoundTripsExactly) {
  const Mesh tube = shapes::revolution({{5, 0}, {8, 0}, {8, 20}, {5, 20}}, 32);
  const TessellationSag s = measure_tessellation_sag(tube, CoordinateStorage::kFloat32);
  const std::string dir = process_dir() + "sag_cache_test";
  std::filesystem::remove_all(dir);
  const std::string key = hulls_key("0123456789abcdef0123456789abcdef", false);
  EXPECT_FALSE(read_cached_hulls(dir, key));
  EXPECT_EQ(write_cached_hulls(dir, key, {{tube.vertices.cols()}, {tube.vertices}, {}, s}), "");
  const auto entry = read_cached_hulls(dir, key);
  ASSERT_TRUE(entry);
  const std::optional<TessellationSag>& back = entry->sag;
  ASSERT_TRUE(back);
  EXPECT_EQ(back->concave, s.concave);
  EXPECT_EQ(back->convex, s.convex);
  EXPECT_EQ(back->resolution, s.resolution);
  EXPECT_EQ(back->creases, s.creases);
  ASSERT_EQ(back->features.size(), s.features.size());
  for (size_t k = 0; k < s.features.size(); ++k) {
    EXPECT_EQ(back->features[k].box.lo, s.features[k].box.lo);
    EXPECT_EQ(back->features[k].box.hi, s.features[k].box.hi);
    EXPECT_EQ(back->features[k].radius, s.features[k].radius);
    EXPECT_EQ(back->features[k].segments, s.features[k].segments);
    ASSERT_EQ(back->features[k].patches.size(), s.features[k].patches.size());
    ASSERT_GT(s.features[k].patches.size(), 1u);  // a ring is in pieces along its surface
    for (size_t q = 0; q < s.features[k].patches.size(); ++q) {
      EXPECT_EQ(back->features[k].patches[q].box.lo, s.features[k].patches[q].box.lo);
      EXPECT_EQ(back->features[k].patches[q].box.hi, s.features[k].patches[q].box.hi);
      EXPECT_EQ(back->features[k].patches[q].concave, s.features[k].patches[q].concave);
      EXPECT_EQ(back->features[k].patches[q].convex, s.features[k].patches[q].convex);
    }
  }
  EXPECT_NE(hulls_key("0123456789abcdef0123456789abcdef", true), key);
}

TEST(AutoTolerance, EachPairGetsTheSagsWhereItsPartsMeet) {
  // One bushing with a coarse bore (16 segments, r 5) and a fine one (128,
  // r 5) 100 apart; a pin in each.
  const Mesh coarse_bore = shapes::revolution({{5, 0}, {8, 0}, {8, 10}, {5, 10}}, 16);
  const Mesh fine_bore =
      shapes::translated(shapes::revolution({{5, 0}, {8, 0}, {8, 10}, {5, 10}}, 128), {100, 0, 0});
  const Part bushing = sag_part("bushing", shapes::joined({coarse_bore, fine_bore}));
  const Mesh pin = shapes::revolution({{0, -5}, {5, -5}, {5, 15}, {0, 15}}, 24);
  const Part coarse_pin = sag_part("pin", pin);
  const Part fine_pin = sag_part("fine_pin", shapes::translated(pin, {100, 0, 0}));
  const double m = 1 + tol::kAutoToleranceMargin;
  const PairTolerance coarse = pair_tolerance(bushing, coarse_pin, {}, "mm");
  EXPECT_NEAR(coarse.value, chord_sag(16, 5) * m, 1e-9);  // the pin is convex: no overlap sag
  EXPECT_EQ(coarse.source, "measured");
  EXPECT_EQ(coarse.basis,
            "bushing: bore r 5 mm, 16 segments, sag 0.0961 mm; pin: no concave tessellated "
            "surface there; coordinate steps 1.42e-14 + 1.78e-15 mm");
  const PairTolerance fine = pair_tolerance(bushing, fine_pin, {}, "mm");
  EXPECT_NEAR(fine.value, chord_sag(128, 5) * m, 1e-9);
  EXPECT_NE(fine.basis.find("128 segments"), std::string::npos) << fine.basis;
  // A declared sag replaces the measured one; the clamps say so.
  Part declared = coarse_pin;
  declared.sag->declared = 0.02;
  const PairTolerance d = pair_tolerance(bushing, declared, {0.2, std::nullopt}, "mm");
  EXPECT_EQ(d.source, "declared");
  EXPECT_EQ(d.value, 0.2);
  EXPECT_NE(d.basis.find("pin: declared sag 0.02 mm"), std::string::npos) << d.basis;
  EXPECT_NE(d.basis.find("raised to the scene's min"), std::string::npos) << d.basis;
}

TEST(AutoTolerance, AFalsePositiveSaysWhichFeatureExplainsIt) {
  std::vector<Part> parts(2);
  parts[0].id = "bushing";
  parts[1].id = "pin";
  PairResult r;
  r.a = 0, r.b = 1;
  r.status = Status::kFalsePositive;
  r.depth_source = "thickness";
  r.depth = 0.08;
  r.tolerance = 0.12;
  r.tolerance_source = "measured";
  r.tolerance_basis = "bushing: bore r 20 mm, 32 segments, sag 0.0963 mm";
  const std::string t = finding_text(r, parts, {}, "mm", 0.0);
  EXPECT_NE(t.find("<= tolerance 0.12 mm"), std::string::npos) << t;
  EXPECT_NE(
      t.find("a tessellation artefact within the band of measured sag (bushing: bore r 20 mm, "
             "32 segments, sag 0.0963 mm)"),
      std::string::npos)
      << t;
  r.status = Status::kInterference;
  r.depth = 0.3;
  EXPECT_NE(finding_text(r, parts, {}, "mm", 0.0).find("> tolerance 0.12 mm; band from measured"),
            std::string::npos);
}

TEST(AutoTolerance, EveryOutputSaysAutoWithEachPairsBandAndNoResolutionWarning) {
  // A 10 mm STL box (float32: a coordinate step) on an inline block, 0.5 deep.
  const std::string dir = process_dir();
  std::ofstream(dir + "auto_box.stl") << "solid b\n"
                                      <<
      [] {
        std::string s;
        const int f[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                              {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
        for (const auto& t : f) {
          s += "facet normal 0 0 0\nouter loop\n";
          for (int k : t)
            s += "vertex " + std::to_string(10 * (k & 1)) + " " +
                 std::to_string(10 * ((k >> 1) & 1)) + " " +
                 std::to_string(10 * ((k >> 2) & 1) + 9.5) + "\n";
          s += "endloop\nendfacet\n";
        }
        return s;
      }() << "endsolid b\n";
  const std::string scene = write_temp("auto_outputs.json", R"({"tolerance": "auto", "parts": [
    {"id": "block", "vertices": [[0,0,0],[10,0,0],[0,10,0],[10,10,0],[0,0,10],[10,0,10],[0,10,10],[10,10,10]]},
    {"id": "box", "mesh": "auto_box.stl"}]})");
  const CliResult r = pdcheck(scene + " -q --no-cache --junit " + dir + "auto.xml --sarif " + dir +
                              "auto.sarif --csv " + dir + "auto.csv --html " + dir + "auto.html");
  EXPECT_EQ(r.code, 1) << r.err;
  const auto rep = nlohmann::json::parse(r.out);
  EXPECT_EQ(rep["tolerance"], "auto");
  for (const auto& p : rep["parts"])
    for (const auto& w : p.value("warnings", nlohmann::json::array()))
      EXPECT_EQ(w.get<std::string>().find("coordinate resolution"), std::string::npos) << w;
  EXPECT_EQ(r.err.find("coordinate resolution"), std::string::npos) << r.err;
  ASSERT_EQ(rep["pairs"].size(), 1u);
  const double band = rep["pairs"][0]["tolerance"];
  EXPECT_GT(band, 0.0);
  const std::string band_text = "tolerance " + short_number(band) + " mm";
  const std::string junit = read_text(dir + "auto.xml");
  EXPECT_NE(junit.find("<property name=\"tolerance\" value=\"auto\"/>"), std::string::npos)
      << junit;
  EXPECT_NE(junit.find(band_text), std::string::npos) << junit;
  EXPECT_EQ(junit.find("tolerance 0 mm"), std::string::npos) << junit;
  const auto sarif = nlohmann::json::parse(read_text(dir + "auto.sarif"));
  EXPECT_EQ(sarif["runs"][0]["properties"]["tolerance"], "auto");
  EXPECT_EQ(sarif["runs"][0]["results"][0]["properties"]["tolerance"], band);
  const std::string csv = read_text(dir + "auto.csv");
  EXPECT_NE(csv.find("," + nlohmann::json(band).dump() + ","), std::string::npos) << csv;
  const nlohmann::json page = page_data(read_text(dir + "auto.html"));
  EXPECT_EQ(page["tolerance"], "auto");
  EXPECT_EQ(page["findings"][0]["tolerance"], band);
  EXPECT_NE(page["findings"][0]["text"].get<std::string>().find(band_text), std::string::npos);
  // The same page from the saved report.
  std::ofstream(dir + "auto.json") << r.out;
  const CliResult html = pdcheck("html " + dir + "auto.json -o " + dir + "auto2.html");
  EXPECT_EQ(html.code, 0) << html.err;
  EXPECT_EQ(page_data(read_text(dir + "auto2.html"))["tolerance"], "auto");
}

TEST(AutoTolerance, CommandLineAutoAndBadValues) {
  // Two inline cubes overlapping by 1e-9: no sag, only their double steps, so
  // auto calls it an interference where a fixed 0.01 calls it a false positive.
  const std::string scene = write_temp("auto_cubes.json", R"({"tolerance": 0.01, "parts": [
    {"id": "a", "vertices": [[0,0,0],[1,0,0],[0,1,0],[1,1,0],[0,0,1],[1,0,1],[0,1,1],[1,1,1]]},
    {"id": "b", "vertices": [[0.999999999,0,0],[2,0,0],[0.999999999,1,0],[2,1,0],
                             [0.999999999,0,1],[2,0,1],[0.999999999,1,1],[2,1,1]]}]})");
  const CliResult fixed = pdcheck(scene + " -q --no-cache");
  EXPECT_EQ(fixed.code, 0) << fixed.err;
  const CliResult a = pdcheck(scene + " -q --no-cache --tolerance auto");
  EXPECT_EQ(a.code, 1) << a.err;
  const auto rep = nlohmann::json::parse(a.out);
  EXPECT_TRUE(rep.contains("tolerance_auto"));
  EXPECT_EQ(rep["tolerance"], "auto");
  ASSERT_EQ(rep["pairs"].size(), 1u);
  const auto& p = rep["pairs"][0];
  EXPECT_EQ(p["status"], "interference");
  EXPECT_EQ(p["tolerance_source"], "measured");
  EXPECT_LT(p["tolerance"].get<double>(), 1e-14);
  EXPECT_TRUE(rep["parts"][0].contains("resolution"));
  const CliResult bad = pdcheck(scene + " -q --tolerance automatic");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--tolerance: expected a length such as 0.05 or 0.05mm"),
            std::string::npos)
      << bad.err;
}
