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
// float32 by assimp, whatever the file's digits.
std::string stl_cube(const std::string& name, double x0, double s) {
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
  for (const auto& t : faces) {
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

TEST(SetupWarnings, UnitsLikeOutliersAreOffTheMedianByAUnitsFactor) {
  const std::vector<std::optional<double>> sizes = {10.0,
                                                    10.0,
                                                    9.0,
                                                    10.0 / 25.4,
                                                    std::nullopt,
                                                    10.0 * 1000 * 1.02,
                                                    10.0 * 304.8 * 0.99,
                                                    10.0 * 25.4 * 1.05,
                                                    11.0};
  const UnitsLikeOutliers o = units_like_outliers(sizes);
  EXPECT_EQ(o.median, 10.0);  // the lower median of the 8 usable sizes
  EXPECT_FALSE(o.factor[0]);
  EXPECT_FALSE(o.factor[2]);
  EXPECT_NEAR(*o.factor[3], 1 / 25.4, 1e-12);
  EXPECT_FALSE(o.factor[4]);
  EXPECT_EQ(o.factor[5], 1000.0);  // 2 % off
  EXPECT_EQ(o.factor[6], 304.8);   // 1 % off
  EXPECT_FALSE(o.factor[7]);       // 5 % off 25.4: not a units factor
  EXPECT_FALSE(o.factor[8]);
  EXPECT_EQ(units_like_outliers({10.0, 10.0 / 25.4}).factor[1], std::nullopt);  // < 3 parts
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
                  "0.393701 mm is 1/25.4 of the assembly's median"));
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
