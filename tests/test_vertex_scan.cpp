// The fast inline-vertex reader (scene/vertex_scan.h) against the general JSON
// parser it stands in for: the same doubles, bit for bit, on generated lists
// in many spellings, and no answer at all (so the general parser reports the
// error) on anything that is not a plain list of number triples.
#include <gtest/gtest.h>

#include <cstring>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "scene/scene.h"
#include "scene/vertex_scan.h"

using namespace pd;

namespace {

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// What the general parser makes of the list: each number as a double.
std::vector<double> general(const std::string& text) {
  std::vector<double> out;
  for (const auto& v : nlohmann::json::parse(text))
    for (const auto& x : v) out.push_back(x.get<double>());
  return out;
}

std::string spelled(std::mt19937_64& rng, double x) {
  std::ostringstream s;
  switch (rng() % 6) {
    case 0:
      s << std::setprecision(17) << x;
      break;
    case 1:
      s << std::setprecision(3) << x;
      break;
    case 2:
      s << std::scientific << std::setprecision(rng() % 20) << x;
      break;
    case 3:
      s << (std::abs(x) < 1e18 ? static_cast<long long>(x) : 7);
      break;
    case 4:
      s << std::setprecision(25) << std::fixed << x;
      break;
    default:
      s << std::uppercase << std::scientific << x;
      break;
  }
  std::string t = s.str();
  const auto e = t.find('e');
  if (rng() % 7 == 0 && e != std::string::npos && t[e + 1] != '-' && t[e + 1] != '+')
    t.replace(e, 1, "e+");
  return t;
}

}  // namespace

TEST(VertexScan, SameDoublesAsTheGeneralParser) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> mag(-300, 300);
  for (int trial = 0; trial < 300; ++trial) {
    std::string text = "[";
    const int n = 1 + static_cast<int>(rng() % 20);
    for (int k = 0; k < n; ++k) {
      text += k ? (rng() % 2 ? ", " : ",\n ") : "";
      text += "[";
      for (int d = 0; d < 3; ++d) {
        double x = std::uniform_real_distribution<double>(-1, 1)(rng) * std::pow(10.0, mag(rng));
        if (rng() % 10 == 0) x = 0;
        std::string num = spelled(rng, x);
        if (rng() % 20 == 0) num = rng() % 2 ? "-0" : "-0.0";
        if (rng() % 20 == 0) num = "123456789012345678901234567890";
        if (rng() % 20 == 0) num = "-9223372036854775809";
        text += (d ? " ,\t" : "") + num;
      }
      text += "]";
    }
    text += " ]";
    const auto got = scan_vertex_array(text);
    ASSERT_TRUE(got) << text;
    const std::vector<double> want = general(text);
    ASSERT_EQ(static_cast<size_t>(got->size()), want.size()) << text;
    for (size_t k = 0; k < want.size(); ++k)
      ASSERT_EQ(bits(got->data()[k]), bits(want[k])) << text << " number " << k;
  }
}

TEST(VertexScan, LeavesEverythingElseToTheGeneralParser) {
  for (const char* text : {"[]",
                           "[[1,2]]",
                           "[[1,2,3,4]]",
                           "[[1,2,3],]",
                           "[[1,2,3]",
                           "[[1,2,3]] x",
                           "[[01,2,3]]",
                           "[[1.,2,3]]",
                           "[[.5,2,3]]",
                           "[[+1,2,3]]",
                           "[[1e,2,3]]",
                           "[[inf,2,3]]",
                           "[[nan,2,3]]",
                           "[[1e999,2,3]]",
                           "[[\"1\",2,3]]",
                           "[[null,2,3]]",
                           "[{\"x\":1}]",
                           "{}",
                           "",
                           "[[1 2 3]]",
                           "[[0x10,2,3]]",
                           "[[1,2,3]][[4,5,6]]"})
    EXPECT_FALSE(scan_vertex_array(text)) << text;
}

// A scene whose vertex list the scanner refuses is read by the general parser,
// whose error names the field; a plain one gives the same scene either way.
TEST(VertexScan, SceneErrorsStillNameTheField) {
  const std::string good = R"({"id": "a", "vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]]})";
  const std::string bad = R"({"id": "b", "vertices": [[0,0,0],[1,0,0],[0,"y",0],[0,0,1]]})";
  try {
    parse_scene_json(R"({"parts": [)" + good + "," + bad + "]}", "s.json", "");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(), "s.json: parts[1].vertices[2][1]: expected a number, got string");
  }
  const SceneSpec s = parse_scene_json(
      R"({"parts": [)" + good + "," + bad.substr(0, 9) + good.substr(9) + "]}", "s.json", "");
  ASSERT_EQ(s.parts.size(), 2u);
  EXPECT_EQ(s.parts[1].vertices->cols(), 4);
  EXPECT_EQ((*s.parts[1].vertices)(0, 1), 1.0);
}
