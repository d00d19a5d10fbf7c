// Set-up smells a run must not absorb in silence (issue 25, item 4): a
// non-rigid placement, a part off its assembly's size by a units factor, a
// tolerance that covers a part, a tolerance below a part's coordinate resolution.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_support.h"
#include "geometry/coordinate_resolution.h"
#include "scene/setup_warnings.h"

using nlohmann::json;
using namespace pd;

namespace {

json cube_along_x(const std::string& id, double x, double s, const json& transform = nullptr) {
  json v = json::array();
  for (int k = 0; k < 8; ++k)
    v.push_back({x + s * (k & 1), s * ((k >> 1) & 1), s * ((k >> 2) & 1)});
  json p = {{"id", id}, {"vertices", v}};
  if (!transform.is_null()) p["transform"] = transform;
  return p;
}

// An ASCII STL cube of side `s` at (x0, x0, x0): its coordinates are stored as
// float32 by assimp, whatever the file's digits. `faces` < 12 leaves the last
// triangles out (an open mesh).
std::string stl_cube(const std::string& name, double x0, double s, int faces_kept = 12) {
  const std::string path = pd_test::process_dir() + name;
  std::ofstream f(path);
  f.precision(17);
  auto v = [&](int k) {
    return std::array<double, 3>{x0 + s * (k & 1), x0 + s * ((k >> 1) & 1),
                                 x0 + s * ((k >> 2) & 1)};
  };
  const int faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                            {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  f << "solid c\n";
  for (int n = 0; n < faces_kept; ++n) {
    const auto& t = faces[n];
    f << "facet normal 0 0 0\nouter loop\n";
    for (int i : t) {
      const auto p = v(i);
      f << "vertex " << p[0] << " " << p[1] << " " << p[2] << "\n";
    }
    f << "endloop\nendfacet\n";
  }
  f << "endsolid c\n";
  return path;
}

std::vector<std::string> warnings_of(const json& report, const std::string& id) {
  for (const auto& p : report["parts"])
    if (p["id"] == id) return p["warnings"].get<std::vector<std::string>>();
  return {};
}

bool has(const std::vector<std::string>& ws, const std::string& what) {
  for (const auto& w : ws)
    if (w.find(what) != std::string::npos) return true;
  return false;
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(CoordinateResolution, IsTheSpacingOfTheStoredNumbers) {
  EXPECT_EQ(coordinate_step(1.0, true), std::ldexp(1.0, -23));
  EXPECT_EQ(coordinate_step(0.75, true), std::ldexp(1.0, -24));
  EXPECT_EQ(coordinate_step(35000.0, true), std::ldexp(1.0, -8));  // 0.0039: issue 25's example
  EXPECT_EQ(coordinate_step(-35000.0, true), std::ldexp(1.0, -8));
  EXPECT_EQ(coordinate_step(1.0, false), std::ldexp(1.0, -52));
  EXPECT_EQ(coordinate_step(0.0, false), std::ldexp(1.0, -1074));  // DBL_MIN's spacing
  // Against the float type itself: the next float above x is x + step.
  for (const float x : {1.0f, 3.0f, 1234.5f, 35000.0f, 1e-20f, 7e30f})
    EXPECT_EQ(coordinate_step(x, true), double(std::nextafter(x, INFINITY)) - x) << x;
  // Carried by the placement's stretch (25.4 for inches in a mm scene), and
  // never finer than the double spacing of the placed coordinates.
  EXPECT_EQ(coordinate_resolution(35000.0, true, 25.4, 1.0), std::ldexp(25.4, -8));
  EXPECT_EQ(coordinate_resolution(1.0, false, 1.0, 1e6), coordinate_step(1e6, false));
}

TEST(SetupWarnings, NonRigidPlacementNamesItsFactors) {
  EXPECT_FALSE(non_rigid_placement(Mat4::Identity()));
  Mat4 rot = Mat4::Identity();
  rot.topLeftCorner<3, 3>() =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  rot(0, 3) = 50;
  EXPECT_FALSE(non_rigid_placement(rot));
  Mat4 six = Mat4::Identity();  // a 45° rotation written with 6 decimals
  six.topLeftCorner<2, 2>() << 0.707107, -0.707107, 0.707107, 0.707107;
  EXPECT_FALSE(non_rigid_placement(six));
  Mat4 scale = rot;
  scale.topLeftCorner<3, 3>() *= 25.4;
  const auto s = non_rigid_placement(scale);
  ASSERT_TRUE(s);
  EXPECT_EQ(setup_warning_kind(*s), kNonRigidPlacement);
  EXPECT_NE(s->find("scales by 25.4"), std::string::npos) << *s;
  Mat4 shear = Mat4::Identity();
  shear(0, 1) = 1.0;
  const auto h = non_rigid_placement(shear);
  ASSERT_TRUE(h);
  EXPECT_NE(h->find("stretches by (1.61803, 1, 0.618034)"), std::string::npos) << *h;
}

UnitsLikePart box_part(double x, double size, double unit_mm = 1.0,
                       std::optional<std::string> format = std::nullopt) {
  UnitsLikePart p;
  p.box = Aabb{Vec3(x, 0, 0), Vec3(x + size, size / 2, size / 2)};
  p.unit_mm = unit_mm;
  p.format_unit = format;
  return p;
}

TEST(SetupWarnings, UnitsLikeOutliersAreOffTheOthersMedianByAUnitsFactor) {
  // Within 3 % of a factor of the others' median, with two or more others.
  const std::vector<UnitsLikePart> parts = {box_part(0, 10),
                                            box_part(0, 10),
                                            box_part(20, 9),
                                            box_part(40, 10 / 25.4),
                                            {},
                                            box_part(60, 10 * 1000 * 1.02),
                                            box_part(0, 10 * 304.8 * 0.99),
                                            box_part(0, 10 * 25.4 * 1.05),
                                            box_part(80, 10)};
  const auto o = units_like_outliers(parts);
  EXPECT_FALSE(o[0]);
  EXPECT_FALSE(o[2]);
  ASSERT_TRUE(o[3]);
  EXPECT_NEAR(o[3]->factor, 1 / 25.4, 1e-12);
  EXPECT_EQ(o[3]->reference, 10.0);  // the median of the 7 other usable sizes
  EXPECT_FALSE(o[4]);
  EXPECT_EQ(o[5]->factor, 1000.0);  // 2 % off
  EXPECT_EQ(o[6]->factor, 304.8);   // 1 % off
  EXPECT_FALSE(o[7]);               // 5 % off 25.4, overlapping the others: not a units factor
  EXPECT_FALSE(o[8]);
  EXPECT_EQ(units_like_warning(parts[3], *o[3], "mm"),
            "size off the assembly's by a units factor: its size 0.393701 mm is 1/25.4 of the "
            "median of the other parts' sizes, 10 mm: likely the in/mm factor 1/25.4 (within 3 % "
            "of it): if its file is in inches, give the part \"units\": \"in\"");
}

TEST(SetupWarnings, AGltfPartWrittenInMillimetresIsFoundInATwoPartScene) {
  // A lid of 60 mm written in mm into a glTF (metres): 60 m, 1000 times away
  // from the origin too, beside a 62 mm box. Both are off each other; the glTF
  // one is said.
  const UnitsLikePart box = box_part(0, 62);
  const UnitsLikePart lid = box_part(1000 * 1, 1000 * 60, 1000.0, "m");
  const auto o = units_like_outliers({box, lid});
  EXPECT_FALSE(o[0]);
  ASSERT_TRUE(o[1]);
  EXPECT_EQ(o[1]->factor, 1000.0);
  const std::string w = units_like_warning(lid, *o[1], "mm");
  EXPECT_NE(w.find("is 968 times the median of the other parts' sizes, 62 mm: likely the m/mm "
                   "factor 1000"),
            w.npos)
      << w;
  EXPECT_NE(w.find("glTF declares metres"), w.npos) << w;
  EXPECT_NE(w.find("give the part \"units\": \"mm\""), w.npos) << w;
  // A glTF part 20 times the others' median already is suspect: a 2 mm pin
  // read as 2 m beside a 100 mm housing; one in proportion is not.
  EXPECT_TRUE(units_like_outliers({box_part(0, 100), box_part(0, 2000, 1000.0, "m")})[1]);
  // A file that states its unit (STEP, converted by the reader) is never flagged.
  UnitsLikePart step = box_part(0, 12000);
  step.unit_from_file = true;
  const auto s = units_like_outliers({box_part(0, 10), box_part(10, 10), step});
  EXPECT_FALSE(s[2]);
  EXPECT_FALSE(units_like_outliers({box_part(0, 100), box_part(0, 150, 1000.0, "m")})[1]);
}

TEST(SetupWarnings, AnInchPartAmongMillimetrePartsIsFoundByItsPlace) {
  // Four mm parts of different sizes in assembly coordinates (x 100 to 400),
  // and a 30 mm bolt at x 200 exported in inches: 1/25.4 of its size and of
  // its distance from the origin, so it meets none of them and scaled back it
  // meets one. Its ratio to the others' median (about 1/59) is no exact factor.
  std::vector<UnitsLikePart> parts = {box_part(100, 40), box_part(140, 80), box_part(220, 60),
                                      box_part(280, 120)};
  parts.push_back(box_part(200 / 25.4, 30 / 25.4));
  const auto o = units_like_outliers(parts);
  for (int k = 0; k < 4; ++k) EXPECT_FALSE(o[k]) << k;
  ASSERT_TRUE(o[4]);
  EXPECT_NEAR(o[4]->factor, 1 / 25.4, 1e-12);
  const std::string w = units_like_warning(parts[4], *o[4], "mm");
  EXPECT_NE(w.find("it meets no other part, and scaled by 25.4 about the origin it meets one"),
            w.npos)
      << w;
  EXPECT_NE(w.find("give the part \"units\": \"in\""), w.npos) << w;
  // A bearing 29,500 mm from the origin (as scripts/make_cad_assemblies.py
  // writes it): housing, rings, shaft and eight 8 mm balls, the outer ring
  // exported in inches. The balls make the others' median 8 mm, so the ring
  // (1.9 mm) is no outlier by size; its place says it.
  std::vector<UnitsLikePart> bearing = {box_part(29452, 108), box_part(29486, 32.6),
                                        box_part(29471, 70.9)};
  for (int k = 0; k < 8; ++k) bearing.push_back(box_part(29484 + 3 * k, 8));
  bearing.push_back(box_part(29478 / 25.4, 48.9 / 25.4));
  const auto b = units_like_outliers(bearing);
  for (size_t k = 0; k + 1 < bearing.size(); ++k) EXPECT_FALSE(b[k]) << k;
  ASSERT_TRUE(b.back());
  EXPECT_NEAR(b.back()->factor, 1 / 25.4, 1e-12);
  // Two parts: the same bolt beside its bracket, found the same way.
  const auto two = units_like_outliers({parts[4], box_part(190, 40)});
  ASSERT_TRUE(two[0]);
  EXPECT_FALSE(two[1]);
}

TEST(SetupWarnings, OrdinaryAssembliesRaiseNoUnitsWarning) {
  // A 4 mm washer on a 100 mm housing (1/25 of it, in its place), a bolt, a
  // shaft and a frame: sizes from 4 to 400 mm, each part meeting another. The
  // frame is 25.0 times the others' median, within 3 % of 25.4, but beyond no
  // other part's size: no units mistake.
  const std::vector<UnitsLikePart> assembly = {box_part(0, 100),    box_part(98, 4),
                                               box_part(90, 16),    box_part(50, 30),
                                               box_part(-300, 400), box_part(60, 8)};
  for (const auto& o : units_like_outliers(assembly)) EXPECT_FALSE(o);
  // An exploded view: every part apart from the others, moved out from the
  // housing in the middle; scaled down they would fall into it, scaled up
  // they fall nowhere.
  const std::vector<UnitsLikePart> exploded = {box_part(-150, 300), box_part(400, 100),
                                               box_part(-700, 60),  box_part(600, 30),
                                               box_part(900, 4),    box_part(1100, 16)};
  for (const auto& o : units_like_outliers(exploded)) EXPECT_FALSE(o);
  // Two parts: the washer on its housing, a 10 times smaller part beside
  // another, a 25 times smaller one apart whose scaled box lands nowhere.
  EXPECT_FALSE(units_like_outliers({box_part(0, 100), box_part(100, 4)})[1]);
  EXPECT_FALSE(units_like_outliers({box_part(0, 100), box_part(120, 10)})[1]);
  const auto apart = units_like_outliers({box_part(0, 100), box_part(300, 4)});
  EXPECT_FALSE(apart[0]);
  EXPECT_FALSE(apart[1]);
  // A 12 m part among 10 mm parts is off by 1000 whatever its place; its
  // unit as read (mm) less the factor is no unit: the warning asks.
  const std::vector<UnitsLikePart> far = {box_part(0, 10), box_part(10, 10), box_part(0, 12000)};
  const auto f = units_like_outliers(far);
  EXPECT_FALSE(f[0]);
  ASSERT_TRUE(f[2]);
  EXPECT_EQ(f[2]->factor, 1000.0);
  EXPECT_NE(
      units_like_warning(far[2], *f[2], "mm").find("is its unit, or the other parts', right?"),
      std::string::npos);
}

// A glTF written in millimetres beside one other part: read in the metres
// glTF declares it is 1000 times too large, and the run says so with the fix.
TEST(SetupWarnings, AGltfInMillimetresInATwoPartSceneIsSaid) {
  const std::string gltf = test::kSource + "/testdata/formats/box_nodes.gltf";
  json parts = {{{"id", "lid"}, {"mesh", gltf}}, cube_along_x("box", 0, 20)};
  const std::string scene = test::write_temp(
      "gltf_mm.json", json{{"units", "mm"}, {"tolerance", 0.1}, {"parts", parts}}.dump());
  const test::CliResult r = test::pdcheck(scene + " --no-cache");
  const json rep = json::parse(r.out);
  EXPECT_TRUE(has(warnings_of(rep, "lid"), "size off the assembly's by a units factor")) << r.err;
  EXPECT_TRUE(has(warnings_of(rep, "lid"), "glTF declares metres")) << r.err;
  EXPECT_TRUE(has(warnings_of(rep, "lid"), "give the part \"units\": \"mm\"")) << r.err;
  EXPECT_FALSE(has(warnings_of(rep, "box"), "units factor"));
  EXPECT_NE(r.err.find("pdcheck: warning: size off the assembly's by a units factor: part \"lid\""),
            std::string::npos)
      << r.err;
  // Given its unit, it is in proportion: no warning.
  parts[0]["units"] = "mm";
  const std::string fixed = test::write_temp(
      "gltf_mm_fixed.json", json{{"units", "mm"}, {"tolerance", 0.1}, {"parts", parts}}.dump());
  EXPECT_EQ(test::pdcheck(fixed + " --no-cache").err.find("units factor"), std::string::npos);
}

// An open mesh says how many boundary edges it has; a part placed twice at
// the same spot is a duplicate pair, said so, not an ordinary interference.
TEST(SetupWarnings, OpenMeshesAndPartsPlacedTwice) {
  const std::string closed = stl_cube("closed_cube.stl", 0, 10);
  const std::string open = stl_cube("open_cube.stl", 0, 10, 11);  // a triangle missing
  const json moved = {{1, 0, 0, 30}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  const std::string scene = test::write_temp(
      "open_twice.json", json{{"units", "mm"},
                              {"tolerance", 0.1},
                              {"parts",
                               {{{"id", "box"}, {"mesh", closed}},
                                {{"id", "box-again"}, {"mesh", closed}},
                                {{"id", "lid"}, {"mesh", open}, {"transform", moved}},
                                cube_along_x("plate", 60, 10),
                                cube_along_x("plate-copy", 60, 10)}}}
                             .dump());
  const test::CliResult r = test::pdcheck(scene + " --no-cache");
  EXPECT_EQ(r.code, 1) << r.err;
  const json rep = json::parse(r.out);
  EXPECT_TRUE(has(warnings_of(rep, "lid"), "open mesh: 3 boundary edges")) << rep.dump();
  EXPECT_FALSE(has(warnings_of(rep, "box"), "open mesh"));
  EXPECT_NE(r.err.find("pdcheck: warning: open mesh: part \"lid\": 3 boundary edges"),
            std::string::npos)
      << r.err;
  // box / box-again: one file placed twice; plate / plate-copy: the same
  // inline cube twice.
  ASSERT_EQ(rep["pairs"].size(), 2u);
  for (const auto& p : rep["pairs"]) {
    const bool twin =
        (p["a"] == "box" && p["b"] == "box-again") || (p["a"] == "plate" && p["b"] == "plate-copy");
    EXPECT_EQ(p.value("duplicate", false), twin) << p.dump();
    if (twin) {
      EXPECT_EQ(p["status"], "interference");
    }
  }
  EXPECT_NE(r.err.find("box / box-again: interference: duplicate: the same geometry at the same "
                       "place (a part placed or exported twice: remove one of them)"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("pdcheck: warning: part placed twice: box / box-again: the same geometry at "
                       "the same place: remove one of them (and 1 more"),
            std::string::npos)
      << r.err;
}

// End to end: each smell is in the part's or pair's warnings and on stderr
// once per kind; a float32 part far from the origin reports its resolution.
TEST(SetupWarnings, RunReportsEachSmellOncePerKind) {
  const json scale2 = {{2, 0, 0, 0}, {0, 2, 0, 0}, {0, 0, 2, 0}, {0, 0, 0, 1}};
  const json far = {{1, 0, 0, -35000}, {0, 1, 0, -35000}, {0, 0, 1, -35000}, {0, 0, 0, 1}};
  const std::string stl = stl_cube("far_cube.stl", 35000, 10);
  json parts = {cube_along_x("a", 0, 10),
                cube_along_x("b", 30, 10),
                cube_along_x("c", 60, 5, scale2),
                cube_along_x("d", 90, 5, scale2),
                cube_along_x("inch", 120, 10 / 25.4),
                {{"id", "far"}, {"mesh", stl}, {"transform", far}}};
  // "far" sits at x 0..10, touching "a" face to face.
  parts[5]["transform"][0][3] = -35010.0;
  const std::string scene = test::write_temp(
      "smells.json", json{{"units", "mm"}, {"tolerance", 0.001}, {"parts", parts}}.dump());
  const test::CliResult r = test::pdcheck(scene);
  ASSERT_NE(r.out, "") << r.err;
  const json rep = json::parse(r.out);
  EXPECT_TRUE(has(warnings_of(rep, "c"), "placement not rigid: the transform scales by 2"));
  EXPECT_TRUE(has(warnings_of(rep, "inch"),
                  "size off the assembly's by a units factor: its size "
                  "0.393701 mm is 1/25.4 of the median of the other parts' sizes, 10 mm"));
  EXPECT_TRUE(has(warnings_of(rep, "far"),
                  "tolerance below coordinate resolution: the tolerance 0.001 mm is below the "
                  "part's coordinate resolution 0.00390625 mm"));
  EXPECT_FALSE(has(warnings_of(rep, "a"), ":"));
  for (const auto& p : rep["parts"])
    if (p["id"] == "far") {
      EXPECT_EQ(p["resolution"], std::ldexp(1.0, -8));
    } else {
      EXPECT_LT(p["resolution"].get<double>(), 1e-12) << p.dump();  // inline doubles
    }
  // stderr: each kind once, the second non-rigid part counted, not repeated.
  EXPECT_EQ(count(r.err, "placement not rigid"), 1u) << r.err;
  EXPECT_NE(r.err.find("pdcheck: warning: placement not rigid: part \"c\": the transform scales "
                       "by 2; CAD placements are rigid: is a unit conversion in the transform? "
                       "(and 1 more: the report's warnings list each)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(count(r.err, "size off the assembly's"), 1u) << r.err;
  EXPECT_EQ(count(r.err, "tolerance below coordinate resolution"), 1u) << r.err;

  // A tolerance at least as large as the smaller part of a flagged pair.
  const std::string big = test::write_temp(
      "big_tol.json", json{{"units", "mm"},
                           {"tolerance", 1000},
                           {"parts", {cube_along_x("p", 0, 10), cube_along_x("q", 2, 10)}}}
                          .dump());
  const test::CliResult t = test::pdcheck(big);
  const json tr = json::parse(t.out);
  ASSERT_EQ(tr["pairs"].size(), 1u);
  EXPECT_EQ(tr["pairs"][0]["status"], "false_positive");
  EXPECT_TRUE(has(tr["pairs"][0]["warnings"].get<std::vector<std::string>>(),
                  "tolerance covers a part: the tolerance 1000 mm is at least the size of the "
                  "smaller part (\"p\", 10 mm): any overlap of this pair passes as a false "
                  "positive"));
  EXPECT_EQ(count(t.err, "pdcheck: warning: tolerance covers a part: p / q:"), 1u) << t.err;
  // Below the part's size: no warning.
  EXPECT_EQ(test::pdcheck(big + " --tolerance 9").err.find("covers"), std::string::npos);
}
