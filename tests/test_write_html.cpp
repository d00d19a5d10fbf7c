// The HTML page (write_html.cpp): ids cannot break out of it, nothing is
// fetched, a missing library is named. Through the binary: test_html.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <nlohmann/json.hpp>
#include <regex>

#include "box_points.h"
#include "geometry/hull.h"
#include "l_prism.h"
#include "page_data.h"
#include "report/write_html.h"
#include "shell_run.h"

using namespace pd;
using pd_test::scratch_dir;

namespace {

using pd_test::box_points;

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = 0; (at = text.find(what, at)) != std::string::npos; at += what.size()) ++n;
  return n;
}

}  // namespace

TEST(HtmlPage, IdsCannotBreakOutOfThePageAndNothingIsFetched) {
  const std::string evil = "</script><script>alert(1)</script>";
  nlohmann::ordered_json report = {{"scene", "<b>scene</b>.json"},
                                   {"units", "mm"},
                                   {"tolerance", 0.1},
                                   {"summary", {{"interference", 1}}},
                                   {"pairs",
                                    {{{"a", evil},
                                      {"b", "{{DATA}}"},
                                      {"fingerprint", "00ff"},
                                      {"status", "interference"},
                                      {"depth", 1.0},
                                      {"direction", {0, 0, 1}},
                                      {"margin", -0.9}},
                                     {{"a", "x"},
                                      {"b", "y"},
                                      {"fingerprint", "11ee"},
                                      {"status", "separated"},
                                      {"depth", 0.0}}}}};
  Part a, b;
  a.id = evil;
  a.pieces.push_back(convex_hull(box_points({0, 0, 0}, {2, 2, 2})));
  b.id = "{{DATA}}";
  b.pieces.push_back(convex_hull(box_points({1, 1, 1}, {3, 3, 3})));
  const std::string page = render_html(report, {a, b});
  EXPECT_EQ(page.find("<script>alert"), std::string::npos);
  EXPECT_EQ(page.find("<b>scene"), std::string::npos);
  EXPECT_EQ(count(page, "</script>"), 3u);  // data, library, page script
  EXPECT_FALSE(std::regex_search(page, std::regex("(src|href)\\s*=\\s*[\"']?(https?:)?//")));
  EXPECT_NE(page.find("default-src 'none'"), std::string::npos);
  EXPECT_NE(page.find("Permission is hereby granted"),
            std::string::npos);  // three.js's MIT licence
  const nlohmann::json data = page_data(page);
  ASSERT_TRUE(data.is_object());
  ASSERT_EQ(data["findings"].size(), 1u);  // separated pairs are no findings
  EXPECT_EQ(data["findings"][0]["a"], evil);
  EXPECT_EQ(data["findings"][0]["b"], "{{DATA}}");
  const auto& view = data["findings"][0]["view"];
  EXPECT_TRUE(view["a"].is_number() && view["b"].is_number() && view["overlap"].is_number());
  const auto& overlap = data["meshes"][view["overlap"].get<int>()];
  EXPECT_EQ(overlap["triangles"], 12);
  // Decoded as the page does (int16 steps of s from o), it is the box [1, 2]³.
  const std::string raw = unbase64(overlap["v"]);
  ASSERT_EQ(raw.size(), 8u * 3 * 2);
  for (size_t k = 0; k < 24; ++k) {
    std::int16_t q;
    std::memcpy(&q, raw.data() + 2 * k, 2);
    const double x = overlap["o"][k % 3].get<double>() + q * overlap["s"].get<double>();
    EXPECT_TRUE(std::fabs(x - 1) < 1e-4 || std::fabs(x - 2) < 1e-4) << x;
  }
}

TEST(HtmlPage, ANonconvexPairShowsItsOwnOverlapAndTheVerdictBanner) {
  // A thickness-decided pair of an L-shaped tray and a block over its inner
  // corner, in a run that could not check everything (exit 3).
  nlohmann::ordered_json report = {{"scene", "tray.json"},
                                   {"units", "mm"},
                                   {"tolerance", 0.1},
                                   {"summary",
                                    {{"parts", 3},
                                     {"part_errors", 1},
                                     {"candidate_pairs", 1},
                                     {"separated", 0},
                                     {"false_positive", 0},
                                     {"interference", 1},
                                     {"error", 0},
                                     {"undecided", 0},
                                     {"unchecked", 2},
                                     {"exit_code", 3}}},
                                   {"pairs",
                                    {{{"a", "tray"},
                                      {"b", "block"},
                                      {"fingerprint", "00ff"},
                                      {"status", "interference"},
                                      {"depth", 2.0},
                                      {"depth_source", "thickness"},
                                      {"depth_bounds", {2.0, 2.0}},
                                      {"direction", {0, 1, 0}},
                                      {"at", {16, 3, 5}},
                                      {"margin", -1.9}}}}};
  Part block;
  block.id = "block";
  block.pieces.push_back(convex_hull(box_points({2, 2, -1}, {30, 30, 11})));
  block.box = {Vec3(2, 2, -1), Vec3(30, 30, 11)};
  block.convex = true;
  const nlohmann::json data =
      page_data(render_html(report, {pd_test::l_prism_part("tray"), block}));
  ASSERT_TRUE(data.is_object());
  EXPECT_EQ(data["verdict"]["state"], "incomplete");
  EXPECT_EQ(data["verdict"]["headline"].get<std::string>().rfind("INCOMPLETE", 0), 0u)
      << data["verdict"];
  const auto& view = data["findings"][0]["view"];
  EXPECT_EQ(view["overlap_of"], "the parts themselves") << view;
  ASSERT_TRUE(view["overlap"].is_number()) << view;
  const auto& overlap = data["meshes"][view["overlap"].get<int>()];
  const std::string raw = unbase64(overlap["v"]);
  ASSERT_GT(raw.size(), 0u);
  for (size_t k = 0; k + 2 < raw.size() / 2; k += 3) {  // each vertex, decoded as the page does
    double x[3];
    for (int d = 0; d < 3; ++d) {
      std::int16_t q;
      std::memcpy(&q, raw.data() + 2 * (k + d), 2);
      x[d] = overlap["o"][d].get<double>() + q * overlap["s"].get<double>();
    }
    EXPECT_TRUE(x[0] < 5 || x[1] < 5)
        << "a drawn overlap point between the tray's arms: " << x[0] << ", " << x[1];
  }
}

TEST(HtmlPage, AMissingLibraryIsNamed) {
  const std::string dir = scratch_dir("html_no_three");
  setenv("PDCHECK_THREE_DIR", dir.c_str(), 1);
  try {
    check_html_assets();
    ADD_FAILURE() << "no error without three.js";
  } catch (const HtmlAssetError& e) {
    EXPECT_NE(std::string(e.what()).find(dir + "/three.min.js"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("libjs-three"), std::string::npos) << e.what();
  }
  unsetenv("PDCHECK_THREE_DIR");
  EXPECT_NO_THROW(check_html_assets());
}
