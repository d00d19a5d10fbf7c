// The pdcheck binary on numbers at the edges of double precision and on
// malformed scene text (issue 11): every case ends with a report or exit 2,
// never an abort.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_support.h"
#include "scene/units.h"

using nlohmann::json;

namespace {

using pd::test::kSource;

using CliRun = pd::test::CliResult;
using pd::test::pdcheck;
using pd::test::write_temp;

// Two tetrahedra that overlap near the origin, every coordinate with the
// exponent suffix `e` ("" for unit size, "e250" for huge), the tolerance too.
std::string overlapping_pair(const std::string& e) {
  auto v = [&](const char* x, const char* y, const char* z) {
    return "[" + std::string(x) + e + "," + y + e + "," + z + e + "]";
  };
  return "{\"tolerance\": 0.01" + e + ", \"parts\": [{\"id\": \"a\", \"vertices\": [" +
         v("0", "0", "0") + "," + v("1", "0", "0") + "," + v("0", "1", "0") + "," +
         v("0", "0", "1") + "]}, {\"id\": \"b\", \"vertices\": [" + v("0.1", "0.1", "0.1") + "," +
         v("2", "0.1", "0.1") + "," + v("0.1", "2", "0.1") + "," + v("0.1", "0.1", "2") +
         "]}], \"pairs\": [[\"a\", \"b\"]]}";
}

}  // namespace

TEST(CliNumbers, InfiniteToleranceIsRefused) {
  for (const char* t : {"inf", "-inf", "nan", "1e999"}) {
    const CliRun r =
        pdcheck(kSource + "/testdata/demo/scene.json --quiet --tolerance " + std::string(t));
    EXPECT_EQ(r.code, 2) << t << ": " << r.err;
    EXPECT_NE(r.err.find("--tolerance"), std::string::npos) << r.err;
  }
}

TEST(CliNumbers, HugeCoordinatesNeverAbortTheRun) {
  // Finite coordinates whose squares overflow: the run still ends with a
  // report in which the pair has a real status or an error with its reason.
  const std::string scene = write_temp("num_huge.json", overlapping_pair("e250"));
  for (const char* method : {"mlsl", "exact"}) {
    const CliRun r = pdcheck(scene + " --quiet -j 1 --method " + method);
    ASSERT_EQ(r.signal, 0) << method << ": " << r.err;
    ASSERT_TRUE(r.code == 1 || r.code == 3) << method << ": exit " << r.code << " " << r.err;
    const json rep = json::parse(r.out);
    ASSERT_EQ(rep["pairs"].size(), 1u);
    const json& p = rep["pairs"][0];
    if (p["status"] == "error") {
      EXPECT_FALSE(p["error"].get<std::string>().empty());
    } else {
      EXPECT_EQ(p["status"], "interference") << p.dump();
      EXPECT_TRUE(p["depth"].is_number()) << p.dump();
    }
  }
}

// The depth of a pair scales with its coordinates, from 1e-300 to 1e307: the
// same interference at every scale, against the exact reference at scale 1.
// Beyond 1e154 the squares in the frame's diagonal used to overflow: both parts
// became "a single point" and the interference was missed (exit 0).
TEST(CliNumbers, DepthScalesWithCoordinatesToTheEdgeOfTheDoubleRange) {
  const std::string unit = write_temp("num_unit.json", overlapping_pair(""));
  const CliRun ref = pdcheck(unit + " --quiet -j 1 --method exact");
  ASSERT_EQ(ref.code, 1) << ref.err;
  const double depth = json::parse(ref.out)["pairs"][0]["depth"];
  ASSERT_GT(depth, 0.1);
  for (const int e : {-300, -160, 160, 250, 307}) {
    const std::string scene =
        write_temp("num_scaled.json", overlapping_pair("e" + std::to_string(e)));
    for (const char* method : {"mlsl", "exact"}) {
      const CliRun r = pdcheck(scene + " --quiet -j 1 --method " + method);
      ASSERT_EQ(r.code, 1) << "1e" << e << " " << method << ": " << r.err << r.out;
      const json p = json::parse(r.out)["pairs"][0];
      ASSERT_EQ(p["status"], "interference") << "1e" << e << " " << method << ": " << p.dump();
      EXPECT_NEAR(p["depth"].get<double>() / std::pow(10.0, e), depth, 1e-9 * depth)
          << "1e" << e << " " << method;
    }
  }
}

// Beyond the double range no frame holds the part: it is an error on the part,
// named, with the reason, and the run says something was not checked (exit 3).
TEST(CliNumbers, APartBeyondTheDoubleRangeIsAnErrorNotAPoint) {
  const std::string scene =
      write_temp("num_beyond.json",
                 "{\"tolerance\": 1, \"parts\": [{\"id\": \"vast\", \"vertices\": [[-1.7e308,0,0], "
                 "[1.7e308,0,0], [0,1.7e308,0], [0,0,1.7e308]]}, {\"id\": \"unit\", \"vertices\": "
                 "[[0,0,0], [1,0,0], [0,1,0], [0,0,1]]}]}");
  const CliRun r = pdcheck(scene + " -j 1");
  ASSERT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("part \"vast\""), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("too large"), std::string::npos) << r.err;
}

// Reading the scene threw out of main (SIGABRT): a number beyond the double
// range, from a file or stdin, and a scene path that is a directory.
TEST(CliNumbers, UnreadableSceneTextIsExit2WithThePlace) {
  const std::string text = "{\"tolerance\": 1,\n \"parts\": [" + std::string(R"({"id": "a",
    "vertices": [[0,0,0],[1,0,1e999]]}]})");
  const std::string file = write_temp("num_overflow.json", text);
  for (const auto& [args, input] : {std::pair<std::string, std::string>{file, ""}, {"-", text}}) {
    const CliRun r = pdcheck(args + " -j 2", input);
    EXPECT_EQ(r.signal, 0) << r.err;
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("line 3, column 35: parts[0].vertices[1][2]: number 1e999"),
              std::string::npos)
        << r.err;
  }
  const CliRun dir = pdcheck(testing::TempDir());
  EXPECT_EQ(dir.signal, 0) << dir.err;
  EXPECT_EQ(dir.code, 2) << dir.err;
  EXPECT_NE(dir.err.find("is a directory"), std::string::npos) << dir.err;
}

// "parts" and "par\u0074s" in one scene: --jobs 1 and --jobs 2 read different
// parts (the threaded splitter matched the raw key, the library the last
// decoded one). Now both refuse the duplicate key, with its path.
TEST(CliNumbers, DuplicateKeysAreRefusedWhateverTheJobs) {
  const std::string tet = R"([[0,0,0],[1,0,0],[0,1,0],[0,0,1]])";
  const std::string scene = write_temp(
      "num_dup.json", R"({"tolerance": 1, "parts": [{"id": "a", "vertices": )" + tet +
                          R"(}, {"id": "b", "vertices": )" + tet +
                          R"(}], "par\u0074s": [{"id": "c", "vertices": )" + tet +
                          R"(}, {"id": "d", "vertices": [[5,0,0],[6,0,0],[5,1,0],[5,0,1]]}]})");
  std::string first;
  for (const char* jobs : {"1", "2"}) {
    const CliRun r = pdcheck(scene + " --quiet --jobs " + jobs);
    EXPECT_EQ(r.code, 2) << jobs << ": " << r.err << r.out;
    EXPECT_NE(r.err.find("parts: duplicate key \"parts\""), std::string::npos) << r.err;
    if (first.empty()) first = r.err;
    EXPECT_EQ(r.err, first);
  }
}

// A 1-unit part crossing the face of a part 1e30 units large by 0.5: in double
// precision the overlap is below any resolvable depth, and the pair read
// `separated`, depth 0, with no sign of it. Now the pair says so; a pair whose
// tolerance is resolvable carries no warning.
TEST(CliNumbers, ADepthBelowTheResolvableScaleIsFlagged) {
  const std::string scene = write_temp("num_deep.json", R"({"tolerance": 0.1, "parts": [
    {"id": "big", "vertices": [[-2e30,-1e30,-1e30],[0,-1e30,-1e30],[-2e30,1e30,-1e30],
      [0,1e30,-1e30],[-2e30,-1e30,1e30],[0,-1e30,1e30],[-2e30,1e30,1e30],[0,1e30,1e30]]},
    {"id": "small", "vertices": [[-0.5,0,0],[1,0,0],[0,1,0],[0,0,1]]}]})");
  for (const char* method : {"mlsl", "exact"}) {
    const CliRun r = pdcheck(scene + " --quiet -j 1 --method " + method);
    ASSERT_EQ(r.signal, 0) << r.err;
    const json p = json::parse(r.out)["pairs"][0];
    ASSERT_TRUE(p.contains("warnings")) << method << ": " << p.dump();
    EXPECT_NE(p["warnings"][0].get<std::string>().find("below the resolvable scale"),
              std::string::npos)
        << p.dump();
    // Every length with its unit (the scene's: mm by default).
    EXPECT_NE(p["warnings"][0].get<std::string>().find("the tolerance 0.1 mm is smaller"),
              std::string::npos)
        << p.dump();
  }
  const std::string unit = write_temp("num_unit2.json", overlapping_pair(""));
  const CliRun r = pdcheck(unit + " --quiet -j 1");
  EXPECT_FALSE(json::parse(r.out)["pairs"][0].contains("warnings")) << r.out;
}

// A length on the command line takes a unit suffix, converted to the scene's
// unit; without one it is in the scene's unit (issue 25).
TEST(CliNumbers, ToleranceTakesAUnitSuffix) {
  EXPECT_EQ(pd::parse_length("0.05mm")->value, 0.05);
  EXPECT_EQ(*pd::parse_length("0.05mm")->unit, "mm");
  EXPECT_EQ(*pd::parse_length("2 in")->unit, "in");
  EXPECT_FALSE(pd::parse_length("0.05")->unit);
  for (const char* bad : {"", "mm", "0.05furlong", "0.05 mmm", "1e999", "nan", "inf"})
    EXPECT_FALSE(pd::parse_length(bad)) << bad;
  EXPECT_DOUBLE_EQ(pd::length_in(*pd::parse_length("2in"), "mm"), 50.8);
  EXPECT_DOUBLE_EQ(pd::length_in(*pd::parse_length("0.5mm"), "cm"), 0.05);
  EXPECT_EQ(pd::length_in(*pd::parse_length("0.5"), "in"), 0.5);

  // The demo (mm): cover / bracket interfere by 2 mm. 0.25 cm = 2.5 mm covers it.
  const std::string demo = kSource + "/testdata/demo/scene.json --quiet";
  const CliRun mm = pdcheck(demo + " --tolerance 2.5mm");
  const CliRun cm = pdcheck(demo + " --tolerance 0.25cm");
  EXPECT_EQ(nlohmann::json::parse(mm.out)["tolerance"], 2.5);
  EXPECT_DOUBLE_EQ(nlohmann::json::parse(cm.out)["tolerance"].get<double>(), 2.5);
  EXPECT_EQ(pdcheck(demo + " --tolerance 0.1mm").code, 1);
  const CliRun bad = pdcheck(demo + " --tolerance 0.1furlong");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("pdcheck: error: --tolerance: expected a length such as 0.05 or 0.05mm"),
            std::string::npos)
      << bad.err;
}
