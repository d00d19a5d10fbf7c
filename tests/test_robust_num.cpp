// Numbers at the edges of double precision: the worker/parent codec, huge
// coordinates, non-finite results (issue 11).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "batch/run.h"
#include "geometry/hull.h"
#include "geometry/motion.h"
#include "scene/scene.h"

namespace {

using pd::PairResult;

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

double from_bits(std::uint64_t b) {
  double x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

// Every double a pair's result may hold, the awkward ones included.
const double kAwkward[] = {std::numeric_limits<double>::quiet_NaN(),
                           -std::numeric_limits<double>::quiet_NaN(),
                           from_bits(0x7ff4000000000123ULL),  // a NaN with a payload
                           std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity(),
                           -0.0,
                           0.0,
                           std::numeric_limits<double>::denorm_min(),
                           std::numeric_limits<double>::max(),
                           -std::numeric_limits<double>::lowest(),
                           0.1,
                           1.0 / 3.0,
                           1e-300};

PairResult with_every_double(double x) {
  PairResult r;
  r.a = 3;
  r.b = 7;
  r.status = pd::Status::kInterference;
  r.depth = x;
  r.direction = pd::Vec3(x, -x, 0.5);
  r.distance = x;
  r.margin = x;
  r.method = "mlsl";
  r.time_ms = x;
  r.fallback = "f";
  r.error = "e";
  r.clearance_min = x;
  pd::MotionTrace m;
  m.steps = 5;
  m.max_depth = x;
  m.t_max_depth = x;
  m.min_distance = x;
  m.t_min_distance = x;
  m.series = {{x, x}, {1.0, x}};
  r.motion = m;
  r.warnings = {"first", "second"};
  return r;
}

}  // namespace

TEST(PairResultCodec, KeepsEveryDoubleBitForBit) {
  for (const double x : kAwkward) {
    const PairResult r = pd::decode_pair_result(pd::encode_pair_result(with_every_double(x)));
    SCOPED_TRACE(x);
    EXPECT_EQ(r.a, 3);
    EXPECT_EQ(r.b, 7);
    EXPECT_EQ(r.status, pd::Status::kInterference);
    EXPECT_EQ(bits(r.depth), bits(x));
    EXPECT_EQ(bits(r.direction.x()), bits(x));
    EXPECT_EQ(bits(r.direction.y()), bits(-x));
    EXPECT_EQ(bits(r.direction.z()), bits(0.5));
    ASSERT_TRUE(r.distance);
    EXPECT_EQ(bits(*r.distance), bits(x));
    EXPECT_EQ(bits(r.margin), bits(x));
    EXPECT_EQ(bits(r.time_ms), bits(x));
    ASSERT_TRUE(r.clearance_min);
    EXPECT_EQ(bits(*r.clearance_min), bits(x));
    ASSERT_TRUE(r.motion);
    EXPECT_EQ(r.motion->steps, 5);
    EXPECT_EQ(bits(r.motion->max_depth), bits(x));
    EXPECT_EQ(bits(r.motion->t_max_depth), bits(x));
    ASSERT_TRUE(r.motion->min_distance);
    EXPECT_EQ(bits(*r.motion->min_distance), bits(x));
    EXPECT_EQ(bits(r.motion->t_min_distance), bits(x));
    ASSERT_EQ(r.motion->series.size(), 2u);
    EXPECT_EQ(bits(r.motion->series[0].first), bits(x));
    EXPECT_EQ(bits(r.motion->series[1].second), bits(x));
    EXPECT_EQ(r.warnings, (std::vector<std::string>{"first", "second"}));
  }
}

TEST(PairResultCodec, RefusesDamagedPayloadsWithAnException) {
  const std::string good = pd::encode_pair_result(with_every_double(1.0));
  EXPECT_NO_THROW(pd::decode_pair_result(good));
  EXPECT_ANY_THROW(pd::decode_pair_result(""));
  EXPECT_ANY_THROW(pd::decode_pair_result("{\"a\": 1}"));
  EXPECT_ANY_THROW(pd::decode_pair_result(good.substr(0, good.size() / 2)));
  // A status outside the enum is not cast into one.
  PairResult bad = with_every_double(1.0);
  bad.status = static_cast<pd::Status>(99);
  EXPECT_ANY_THROW(pd::decode_pair_result(pd::encode_pair_result(bad)));
}

TEST(PairResultCodec, AnUnreadableWorkerAnswerIsAnErrorOnItsPairOnly) {
  const PairResult good = pd::pair_result_from_worker(
      true, pd::encode_pair_result(with_every_double(2.0)), 3, 7, "mlsl");
  EXPECT_EQ(good.status, pd::Status::kInterference);
  EXPECT_EQ(good.depth, 2.0);
  for (const std::string& payload :
       {std::string(), std::string("{\"d\": null}"), std::string("\x85garbage")}) {
    const PairResult r = pd::pair_result_from_worker(true, payload, 4, 9, "exact");
    EXPECT_EQ(r.status, pd::Status::kError);
    EXPECT_EQ(r.a, 4);
    EXPECT_EQ(r.b, 9);
    EXPECT_EQ(r.method, "exact");
    EXPECT_NE(r.error.find("worker result unreadable"), std::string::npos) << r.error;
  }
  const PairResult crashed = pd::pair_result_from_worker(false, "worker crashed", 1, 2, "mlsl");
  EXPECT_EQ(crashed.status, pd::Status::kError);
  EXPECT_EQ(crashed.error, "worker crashed");
}

// The hull's dimension test works in the frame of the point set: its scale
// must not overflow (coordinates beyond ~1e154 squared) or underflow.
TEST(HugeCoordinates, HullDimensionIsScaleFree) {
  pd::Points tet(3, 5);
  tet << 0, 1, 0, 0, 0.2,  //
      0, 0, 1, 0, 0.2,     //
      0, 0, 0, 1, 0.2;
  for (const double s : {1e-300, 1e-160, 1.0, 1e160, 1e250, 1e307}) {
    const pd::Hull h = pd::convex_hull(tet * s);
    EXPECT_EQ(h.dimension, 3) << s;
    EXPECT_EQ(h.vertices.cols(), 4) << s;
    EXPECT_TRUE(h.warnings.empty()) << s;
  }
  // A set whose box half-diagonal exceeds the double range has no frame.
  pd::Points vast(3, 4);
  vast << -1.7e308, 1.7e308, 0, 0,  //
      0, 0, 1.7e308, 0,             //
      0, 0, 0, 1.7e308;
  EXPECT_THROW(pd::convex_hull(vast), std::invalid_argument);
}

namespace {

// The error of a scene with a moving pair that interferes at dt = 1 (b moves
// through a), under the given motion grid; "" when it reads.
std::string grid_error(const std::string& grid) {
  const std::string text = R"({"tolerance": 0.01, "checks": {"motion": {)" + grid + R"(}},
    "parts": [{"id": "a", "vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]]},
              {"id": "b", "motion": {"velocity": [-1,0,0]},
               "vertices": [[3,0,0],[4,0,0],[3,1,0],[3,0,1]]}]})";
  try {
    pd::parse_scene_json(text, "s.json", "");
  } catch (const pd::SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// More than 2^63 grid steps used to cast to long out of range, pass the step
// cap and skip the sweep: the interfering pair was `separated`, exit 0.
TEST(TimeGridLimits, HugeStepCountsAreRefusedNamingTheField) {
  EXPECT_EQ(grid_error(R"("t1": 4, "dt": 1)"), "");
  EXPECT_EQ(grid_error(R"("t1": 4, "dt": 1e-300)"),
            "s.json: checks.motion.dt: gives 4e+300 time steps, more than 1000000: use a larger "
            "dt");
  EXPECT_EQ(grid_error(R"("t1": 9.3e18)"),
            "s.json: checks.motion.dt: gives 9.3e+18 time steps, more than 1000000: use a larger "
            "dt");
  EXPECT_EQ(grid_error(R"("t0": -1e308, "t1": 1e308)"),
            "s.json: checks.motion.t1: t1 - t0 is beyond the double range");
  EXPECT_EQ(grid_error(R"("t1": 999999)"), "");  // 1,000,000 steps: the cap itself
  EXPECT_NE(grid_error(R"("t1": 1000000)").find("more than 1000000"), std::string::npos);
  // Times that cannot differ by dt at their magnitude would repeat one time.
  EXPECT_EQ(grid_error(R"("t0": 1e20, "t1": 1.000000000000002e20)"),
            "s.json: checks.motion.dt: below the resolution of double-precision times at |t| = "
            "1e+20: use a larger dt or shift t0");
}

TEST(TimeGridLimits, StepsNeverCastOutOfRange) {
  EXPECT_EQ((pd::TimeGrid{0, 4, 1}).steps(), 5);
  EXPECT_EQ((pd::TimeGrid{0, 4, 0.5}).steps(), 9);
  EXPECT_THROW((pd::TimeGrid{0, 4, 1e-300}).steps(), std::domain_error);
  EXPECT_THROW((pd::TimeGrid{-1e308, 1e308, 1}).steps(), std::domain_error);
  EXPECT_THROW((pd::TimeGrid{0, 9.3e18, 1}).steps(), std::domain_error);
}

// solver.grid / solver.gs_local up to 100,000 meant hours for one pair.
TEST(SolverLimits, GridAndGsLocalAreBounded) {
  auto error = [](const std::string& solver) -> std::string {
    try {
      pd::parse_scene_json(R"({"tolerance": 1, "parts": [], "solver": {)" + solver + "}}", "s.json",
                           "");
    } catch (const pd::SceneError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(error(R"("grid": 1000, "gs_local": 10)"), "");
  EXPECT_EQ(error(R"("grid": 1001)"), "s.json: solver.grid: expected an integer from 1 to 1000");
  EXPECT_EQ(error(R"("grid": 100000)"), "s.json: solver.grid: expected an integer from 1 to 1000");
  EXPECT_EQ(error(R"("gs_local": 11)"),
            "s.json: solver.gs_local: expected an integer from 1 to 10");
  EXPECT_EQ(error(R"("samples": 100000)"), "");
}
