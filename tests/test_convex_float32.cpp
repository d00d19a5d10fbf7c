// Convex parts stored in float32 (issue 44): tessellated spheres, plates, boxes,
// needles and tilted bolt-like prisms, convex by construction, whose float32
// rounding far from the origin leaves concavities of the order of the
// coordinates' step. Each is solved as convex: its depth is the exact
// penetration depth of the hulls of the coordinates as stored, scored against
// the exact reference (corpus/exact_reference.h), at several placements far
// from the origin and at tolerances below the coordinates' rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>

#include "corpus/cad_shapes.h"
#include "corpus/exact_reference.h"
#include "geometry/hull.h"
#include "random_rotation.h"
#include "shell_run.h"
#include "stl_file.h"

using namespace pd;
using namespace pd::shapes;
using nlohmann::json;

namespace convex_float32 {

Mesh sphere(double r, int segments) {
  std::vector<Vec2> profile{{0, -r}};
  const int rings = segments / 2;
  for (int k = 1; k < rings; ++k) {
    const double t = M_PI * k / rings;
    profile.emplace_back(r * std::sin(t), -r * std::cos(t));
  }
  profile.emplace_back(0, r);
  return revolution(profile, segments);
}

Mesh moved(Mesh m, const Eigen::Matrix3d& R, const Vec3& t) {
  m.vertices = (R * m.vertices).colwise() + t;
  return m;
}

struct FloatCase {
  std::string name;
  Mesh a, b;  ///< in the pair's own frame
};

// Pairs overlapping by construction, in the pair's frame; b tilted in some.
std::vector<FloatCase> cases(std::mt19937& rng) {
  const auto tilt = [&](double angle) {
    std::normal_distribution<double> n(0, 1);
    return Eigen::AngleAxisd(angle, Vec3(n(rng), n(rng), n(rng)).normalized()).toRotationMatrix();
  };
  const Mesh plate = box({-30, -30, -2.5}, {30, 30, 2.5});
  const Mesh block = box({-15, -10, -12.5}, {15, 10, 12.5});
  const Mesh needle = cylinder({0, 0}, 0.5, -50, 50, 12);
  const Mesh bolt = prism(circle({0, 0}, 6.5 / std::cos(M_PI / 6), 6), -20, 20);
  return {
      {"sphere 4 mm into a plate", sphere(10, 32), moved(plate, tilt(0.1), {0, 0, 12.5 - 4})},
      {"needle through a block", needle, moved(block, tilt(0.3), {0, 0.2, 3})},
      {"tilted bolt 1 mm into a plate", moved(bolt, tilt(0.15), {0, 0, 21.5}), plate},
      {"block corner into a block", block, moved(block, tilt(0.7), {24, 9, 5})},
      {"sphere into a sphere", sphere(10, 20), moved(sphere(8, 12), tilt(1.0), {16.5, 0, 0})},
      {"needle through a plate", moved(needle, tilt(0.4), {3, -2, 0}), plate},
      {"lid 1 mm into a block", moved(plate, tilt(0.0), {0, 0, 12.5 + 2.5 - 1}), block},
  };
}

// The points of a mesh as a float32 file stores them (and pdcheck reads them).
Points stored(const Mesh& m) {
  return float32(m).vertices;
}

}  // namespace convex_float32

using namespace convex_float32;

TEST(ConvexFloat32, PartsConvexUpToTheirRoundingGetTheExactHullDepth) {
  std::mt19937 rng(44);
  const std::string dir = pd_test::scratch_dir("convex_float32");
  json parts = json::array(), pairs = json::array();
  struct Expected {
    std::string name;
    double depth;
  };
  std::map<std::string, Expected> expected;  // by "a|b"
  int n = 0;
  for (const double x : {1.0e3, 2.2e4, 3.5e4}) {  // placements far from the origin
    for (const FloatCase& c : cases(rng)) {
      const Eigen::Matrix3d R = pd_test::random_rotation(rng);
      const Vec3 t(x, 0.3 * x - 2000, -0.1 * x + 500);
      const Mesh a = moved(c.a, R, t), b = moved(c.b, R, t);
      const std::string ia = "a" + std::to_string(n), ib = "b" + std::to_string(n);
      ++n;
      pd::test::write_binary_stl(dir + "/" + ia + ".stl", a);
      pd::test::write_binary_stl(dir + "/" + ib + ".stl", b);
      parts.push_back({{"id", ia}, {"mesh", ia + ".stl"}});
      parts.push_back({{"id", ib}, {"mesh", ib + ".stl"}});
      pairs.push_back({ia, ib});
      const double exact = testgen::exact_reference_depth(convex_hull(stored(a)).vertices,
                                                          convex_hull(stored(b)).vertices)
                               .depth;
      ASSERT_GT(exact, 0.5) << c.name;
      expected[ia + "|" + ib] = {c.name + " at x = " + std::to_string(x), exact};
    }
  }
  // A tolerance below the float32 step there (0.002-0.004 mm): the concavity
  // tolerance alone would call most rounded parts nonconvex.
  for (const double tolerance : {1e-3}) {  // 12 of the 21 pairs took the thickness path
    std::ofstream(dir + "/scene.json") << json{
        {"version", 1},
        {"units", "mm"},
        {"tolerance", tolerance},
        {"parts", parts},
        {"pairs", pairs}}.dump();
    const pd_test::ShellRun run = pd_test::shell(dir, "\"$PDCHECK\" scene.json --no-cache --quiet");
    ASSERT_EQ(run.code, 1) << run.err;
    const json report = json::parse(run.out);
    ASSERT_EQ(report["pairs"].size(), expected.size());
    for (const json& p : report["pairs"]) {
      const Expected& e = expected.at(p["a"].get<std::string>() + "|" + p["b"].get<std::string>());
      SCOPED_TRACE(e.name + ", tolerance " + std::to_string(tolerance));
      EXPECT_EQ(p["depth_source"], "hull");
      EXPECT_NEAR(p["depth"].get<double>(), e.depth, 1e-9 * e.depth);
    }
  }
}
