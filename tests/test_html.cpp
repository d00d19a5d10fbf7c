// The HTML report's geometry (overlaps, caps, decimation), its page (escaping,
// nothing fetched) and its command line (--html, pdcheck html). The page in a
// real browser: tests/browser/test_html_report.py.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>

#include "box_points.h"
#include "geometry/hull.h"
#include "page_data.h"
#include "report/html_geometry.h"
#include "report/write_html.h"
#include "shell_run.h"

using namespace pd;
using pd_test::scratch_dir;
using pd_test::shell;
using pd_test::ShellRun;

namespace {

using pd_test::box_points;

Points mesh_points(const WebMesh& m) {
  Points p(3, static_cast<long>(m.vertex_count()));
  for (size_t k = 0; k < m.vertex_count(); ++k)
    p.col(static_cast<long>(k)) =
        m.origin + Vec3(m.positions[3 * k], m.positions[3 * k + 1], m.positions[3 * k + 2]);
  return p;
}

bool inside(const HullFacets& f, const Vec3& x, double eps) {
  for (size_t k = 0; k < f.normals.size(); ++k)
    if (f.normals[k].dot(x) + f.offsets[k] > eps) return false;
  return true;
}

std::string unbase64(const std::string& in) {
  const std::string abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  unsigned bits = 0;
  int n = 0;
  for (char c : in) {
    if (c == '=') break;
    bits = (bits << 6) | static_cast<unsigned>(abc.find(c));
    if ((n += 6) >= 8) out += static_cast<char>((bits >> (n -= 8)) & 0xff);
  }
  return out;
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = 0; (at = text.find(what, at)) != std::string::npos; at += what.size()) ++n;
  return n;
}

}  // namespace

TEST(HtmlGeometry, OverlapOfTwoBoxesIsTheirIntersection) {
  const auto m = overlap_web_mesh(box_points({0, 0, 0}, {2, 2, 2}),
                                  box_points({1, 0.5, -1}, {3, 1.5, 1}), 4000);
  ASSERT_TRUE(m);
  const Points p = mesh_points(*m);
  EXPECT_EQ(p.cols(), 8);
  EXPECT_TRUE(p.rowwise().minCoeff().isApprox(Vec3(1, 0.5, 0), 1e-6)) << p.rowwise().minCoeff();
  EXPECT_TRUE(p.rowwise().maxCoeff().isApprox(Vec3(2, 1.5, 1), 1e-6)) << p.rowwise().maxCoeff();
  EXPECT_EQ(m->triangles.size(), 12u);
}

TEST(HtmlGeometry, OverlapOfRandomPolytopesHoldsExactlyThePointsInBoth) {
  // Every overlap vertex is in both hulls, and every point in both hulls is in
  // the overlap: the overlap is A ∩ B (up to rounding), on generated cases.
  std::mt19937 rng(7);
  std::normal_distribution<double> n01;
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  int overlapping = 0;
  for (int c = 0; c < 20; ++c) {
    Points a(3, 30), b(3, 30);
    for (long k = 0; k < 30; ++k) {
      a.col(k) = Vec3(n01(rng), n01(rng), n01(rng));
      b.col(k) = Vec3(n01(rng), n01(rng), n01(rng)) * 0.8 + Vec3(0.9, 0.2, -0.1);
    }
    HullFacets fa, fb;
    ASSERT_TRUE(hull_facets(convex_hull(a).vertices, fa));
    ASSERT_TRUE(hull_facets(convex_hull(b).vertices, fb));
    const auto m = overlap_web_mesh(a, b, 4000);
    if (!m) continue;
    ++overlapping;
    const Points p = mesh_points(*m);
    for (long k = 0; k < p.cols(); ++k) {
      EXPECT_TRUE(inside(fa, p.col(k), 1e-5)) << "case " << c;
      EXPECT_TRUE(inside(fb, p.col(k), 1e-5)) << "case " << c;
    }
    HullFacets fo;
    ASSERT_TRUE(hull_facets(p, fo));
    int both = 0;
    for (int s = 0; s < 2000; ++s) {
      const Vec3 x(u(rng), u(rng), u(rng));
      if (!inside(fa, x, -1e-5) || !inside(fb, x, -1e-5)) continue;
      ++both;
      EXPECT_TRUE(inside(fo, x, 1e-5))
          << "case " << c << ": a point in A and B is not in the overlap";
    }
    EXPECT_GT(both, 0) << "case " << c;
  }
  EXPECT_GT(overlapping, 10);
}

TEST(HtmlGeometry, ApartOrTouchingHullsHaveNoOverlap) {
  EXPECT_FALSE(
      overlap_web_mesh(box_points({0, 0, 0}, {1, 1, 1}), box_points({2, 0, 0}, {3, 1, 1}), 100));
  EXPECT_FALSE(
      overlap_web_mesh(box_points({0, 0, 0}, {1, 1, 1}), box_points({1, 0, 0}, {2, 1, 1}), 100));
}

TEST(HtmlGeometry, LargeHullsAreCappedAndSayHow) {
  std::mt19937 rng(3);
  std::normal_distribution<double> n01;
  Points sphere(3, 6000);
  for (long k = 0; k < sphere.cols(); ++k)
    sphere.col(k) = Vec3(n01(rng), n01(rng), n01(rng)).normalized();
  Part part;
  part.id = "ball";
  part.pieces.push_back(convex_hull(sphere));
  const WebMesh m = part_web_mesh(part, 1000);
  EXPECT_LE(m.triangles.size(), 1000u);
  EXPECT_GT(m.triangles.size(), 500u);
  EXPECT_NE(m.how.find("hull of 502 of its 6,000 hull vertices"), std::string::npos) << m.how;
  const WebMesh whole = part_web_mesh(part, 20000);
  EXPECT_EQ(whole.triangles.size(), 2 * 6000u - 4);
  EXPECT_NE(whole.how.find("convex hull"), std::string::npos) << whole.how;
}

TEST(HtmlGeometry, LargeMeshesAreClusteredUnderTheCap) {
  // A wavy sheet of 2 × 120 × 120 triangles: nonconvex, so shown as a mesh.
  const int n = 121;
  auto mesh = std::make_shared<Mesh>();
  mesh->vertices.resize(3, n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) mesh->vertices.col(i * n + j) = Vec3(i, j, 5 * std::sin(i * 0.2));
  mesh->triangles.resize(3, 2 * (n - 1) * (n - 1));
  long t = 0;
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const int v = i * n + j;
      mesh->triangles.col(t++) = Eigen::Vector3i(v, v + n, v + 1);
      mesh->triangles.col(t++) = Eigen::Vector3i(v + 1, v + n, v + n + 1);
    }
  Part part;
  part.id = "sheet";
  part.pieces.push_back(convex_hull(mesh->vertices));
  part.surface.emplace();
  part.surface->mesh = mesh;
  const WebMesh m = part_web_mesh(part, 4000);
  EXPECT_LE(m.triangles.size(), 4000u);
  EXPECT_GT(m.triangles.size(), 1000u);  // still a sheet, not its hull (12-ish triangles)
  EXPECT_NE(m.how.find("clustered"), std::string::npos) << m.how;
  const Points p = mesh_points(m);  // the outline is kept: the same box within a cell
  EXPECT_LT((p.rowwise().minCoeff() - Vec3(0, 0, -5)).norm(), 2.0);
  EXPECT_LT((p.rowwise().maxCoeff() - Vec3(120, 120, 5)).norm(), 2.0);
  const WebMesh full = part_web_mesh(part, 100000);
  EXPECT_EQ(full.triangles.size(), static_cast<size_t>(2 * 120 * 120));
}

TEST(HtmlGeometry, Base64) {
  EXPECT_EQ(base64("", 0), "");
  EXPECT_EQ(base64("f", 1), "Zg==");
  EXPECT_EQ(base64("fo", 2), "Zm8=");
  EXPECT_EQ(base64("foo", 3), "Zm9v");
  EXPECT_EQ(base64("foobar", 6), "Zm9vYmFy");
  const unsigned char high[] = {0xff, 0xfe, 0x00};
  EXPECT_EQ(base64(high, 3), "//4A");
}

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

TEST(HtmlCli, RunAndSavedReportGiveTheSameFindings) {
  const std::string dir = scratch_dir("html_cli");
  const ShellRun run = shell(dir, "\"$PDCHECK\" \"$DEMO\" -q -o r.json --html run.html");
  EXPECT_EQ(run.code, 1) << run.err;
  const ShellRun saved = shell(dir, "\"$PDCHECK\" html r.json -o saved.html");
  EXPECT_EQ(saved.code, 0) << saved.err;
  EXPECT_NE(saved.err.find("wrote saved.html"), std::string::npos) << saved.err;
  const nlohmann::json a = page_data(pd_test::read_text(dir + "/run.html"));
  const nlohmann::json b = page_data(pd_test::read_text(dir + "/saved.html"));
  ASSERT_TRUE(a.is_object() && b.is_object());
  const nlohmann::json report = nlohmann::json::parse(pd_test::read_text(dir + "/r.json"));
  size_t findings = 0;
  for (const auto& p : report["pairs"]) findings += p["status"] != "separated";
  EXPECT_EQ(a["findings"].size(), findings);
  EXPECT_EQ(b["findings"].size(), findings);
  for (size_t k = 0; k < findings; ++k) {
    EXPECT_EQ(a["findings"][k]["fingerprint"], b["findings"][k]["fingerprint"]);
    EXPECT_FALSE(b["findings"][k]["view"]["a"].is_null()) << k;
  }
  EXPECT_EQ(a["findings"][0]["status"], "interference");
  // Nearby parts as context: known ids, never the pair's own parts.
  const auto& context = a["findings"][0]["view"]["context"];
  EXPECT_FALSE(context.empty());
  for (const auto& k : context) {
    const std::string id = a["boxes"][k.get<size_t>()][0];
    EXPECT_NE(id, a["findings"][0]["a"]);
    EXPECT_NE(id, a["findings"][0]["b"]);
  }
}

TEST(HtmlCli, BaselineStatesAndAMovedReport) {
  // With --baseline the page carries the state counts and each finding's state;
  // a report moved beside its scene still finds it.
  const std::string dir = scratch_dir("html_cli_baseline");
  const ShellRun r =
      shell(dir,
            "cp -r \"$(dirname \"$DEMO\")\" demo && cd demo && \"$PDCHECK\" scene.json -q "
            "-o ../old.json; \"$PDCHECK\" scene.json -q -o ../r.json --baseline "
            "../old.json --html ../run.html; cd .. && mkdir moved && cp r.json "
            "demo/r.json && \"$PDCHECK\" html demo/r.json -o moved/p.html");
  EXPECT_EQ(r.code, 0) << r.err;
  const nlohmann::json run = page_data(pd_test::read_text(dir + "/run.html"));
  ASSERT_TRUE(run.is_object());
  EXPECT_EQ(run["summary"]["baseline"]["unchanged"], 3) << run["summary"];
  EXPECT_EQ(run["findings"][0]["baseline_state"], "unchanged");
  const nlohmann::json moved = page_data(pd_test::read_text(dir + "/moved/p.html"));
  ASSERT_TRUE(moved.is_object());
  EXPECT_TRUE(moved["notes"].empty()) << moved["notes"];
  EXPECT_FALSE(moved["findings"][0]["view"]["a"].is_null());
}

TEST(HtmlCli, UnreadablePartsAreNamedAndTheRestIsShown) {
  const std::string dir = scratch_dir("html_cli_missing");
  const ShellRun r = shell(dir,
                           "cp -r \"$(dirname \"$DEMO\")\" demo && \"$PDCHECK\" demo/scene.json -q "
                           "-o r.json; rm demo/cover.obj; \"$PDCHECK\" html r.json -o p.html");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("part \"cover\""), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cover.obj"), std::string::npos) << r.err;
  const nlohmann::json data = page_data(pd_test::read_text(dir + "/p.html"));
  ASSERT_TRUE(data.is_object());
  bool noted = false;
  for (const auto& n : data["notes"])
    noted |= n.get<std::string>().find("cover") != std::string::npos;
  EXPECT_TRUE(noted) << data["notes"];
  for (const auto& f : data["findings"])  // the other parts keep their views
    if (f["a"] != "cover" && f["b"] != "cover") {
      EXPECT_FALSE(f["view"]["a"].is_null());
    }
}

TEST(HtmlCli, BadInputsFailBeforeAnyWork) {
  const std::string dir = scratch_dir("html_cli_bad");
  const ShellRun no_report = shell(dir, "\"$PDCHECK\" html none.json -o p.html");
  EXPECT_EQ(no_report.code, 2);
  EXPECT_NE(no_report.err.find("none.json"), std::string::npos) << no_report.err;
  const ShellRun not_report = shell(dir, "\"$PDCHECK\" html \"$DEMO\" -o p.html");
  EXPECT_EQ(not_report.code, 2);
  EXPECT_NE(not_report.err.find("not a pdcheck JSON report"), std::string::npos) << not_report.err;
  const ShellRun bad_path = shell(dir, "\"$PDCHECK\" \"$DEMO\" -q --html missing/p.html");
  EXPECT_EQ(bad_path.code, 2);
  EXPECT_NE(bad_path.err.find("--html"), std::string::npos) << bad_path.err;
  const ShellRun no_three = shell(
      dir,
      "mkdir empty; PDCHECK_THREE_DIR=empty \"$PDCHECK\" \"$DEMO\" -q -o r.json --html p.html");
  EXPECT_EQ(no_three.code, 2);
  EXPECT_NE(no_three.err.find("three.min.js"), std::string::npos) << no_three.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/r.json")) << "the run went ahead";
  const ShellRun stdin_scene =
      shell(dir,
            "printf %s \"{\\\"scene\\\": \\\"-\\\", \\\"pairs\\\": []}\" > s.json; "
            "\"$PDCHECK\" html s.json -o p.html");
  EXPECT_EQ(stdin_scene.code, 2);
  EXPECT_NE(stdin_scene.err.find("standard input"), std::string::npos) << stdin_scene.err;
  const ShellRun bad_type = shell(dir,
                                  "printf \"{\\\"scene\\\": \\\"%s\\\", \\\"pairs\\\": "
                                  "[{\\\"status\\\": 5}]}\" \"$DEMO\" > t.json; "
                                  "\"$PDCHECK\" html t.json -o p.html");
  EXPECT_EQ(bad_type.code, 2);
  EXPECT_NE(bad_type.err.find("t.json: not a pdcheck JSON report"), std::string::npos)
      << bad_type.err;
  const ShellRun no_scene = shell(dir, "\"$PDCHECK\" -q");
  EXPECT_EQ(no_scene.code, 2);
  EXPECT_NE(no_scene.err.find("scene is required"), std::string::npos) << no_scene.err;
}
