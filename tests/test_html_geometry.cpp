// The HTML report's geometry (html_geometry.cpp): overlaps, caps, decimation,
// base64.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>

#include "box_points.h"
#include "geometry/hull.h"
#include "l_prism.h"
#include "page_data.h"
#include "report/html_geometry.h"

using namespace pd;

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

TEST(HtmlGeometry, ANonconvexPairsOverlapIsThePartsOwnNotTheirHulls) {
  // An L-shaped tray (arms 4 wide) and a block over its inner corner: they
  // share two strips along the arms; their hulls share most of the block.
  const Part tray = pd_test::l_prism_part("tray");
  Part block;
  block.id = "block";
  block.pieces.push_back(convex_hull(box_points({2, 2, -1}, {30, 30, 11})));
  block.box = {Vec3(2, 2, -1), Vec3(30, 30, 11)};
  block.convex = true;
  const SolidOverlap solid = solid_overlap_web_mesh(tray, block, 4000);
  ASSERT_TRUE(solid.mesh) << solid.note;
  EXPECT_LE(solid.mesh->triangles.size(), 4000u);
  const Points p = mesh_points(*solid.mesh);
  const double step = 1.0;  // a triangle is kept by its centre: its corners may be a split away
  for (long k = 0; k < p.cols(); ++k) {
    const Vec3 x = p.col(k);
    EXPECT_TRUE(x.x() > 2 - step && x.x() < 30 + step && x.y() > 2 - step && x.y() < 30 + step &&
                x.z() > -step && x.z() < 10 + step && (x.x() < 4 + step || x.y() < 4 + step))
        << "a point of the drawn overlap outside the tray and the block: " << x.transpose();
  }
  // It reaches along both arms to the block's far faces, and holds the tray's
  // top face where the block covers it (two large triangles whose corners all
  // lie outside the block).
  EXPECT_NEAR(p.row(0).maxCoeff(), 30, step);
  EXPECT_NEAR(p.row(1).maxCoeff(), 30, step);
  bool on_the_top_face = false;
  for (long k = 0; k < p.cols(); ++k)
    on_the_top_face |= std::fabs(p(2, k) - 10) < 1e-3 && p(0, k) > 10 && p(0, k) < 25 &&
                       p(1, k) > 2 && p(1, k) < 4;
  EXPECT_TRUE(on_the_top_face);
  // The hulls' overlap (what the page drew before) fills the corner between the arms.
  const auto hulls = overlap_web_mesh(part_vertices(tray), part_vertices(block), 4000);
  ASSERT_TRUE(hulls);
  const Points q = mesh_points(*hulls);
  bool between_the_arms = false;
  for (long k = 0; k < q.cols(); ++k) between_the_arms |= q(0, k) > 10 && q(1, k) > 10;
  EXPECT_TRUE(between_the_arms);

  // Apart: nothing, and nothing to explain. An open mesh: nothing, and why.
  Part far = block;
  far.pieces = {convex_hull(box_points({100, 0, 0}, {110, 10, 10}))};
  far.box = {Vec3(100, 0, 0), Vec3(110, 10, 10)};
  const SolidOverlap apart = solid_overlap_web_mesh(tray, far, 4000);
  EXPECT_FALSE(apart.mesh);
  EXPECT_EQ(apart.note, "");
  Part open = pd_test::l_prism_part("open tray");
  auto cut = std::make_shared<Mesh>(*open.surface->file_mesh);
  cut->triangles.conservativeResize(3, cut->triangles.cols() - 1);
  open.surface->file_mesh = cut;
  const SolidOverlap not_solid = solid_overlap_web_mesh(open, block, 4000);
  EXPECT_FALSE(not_solid.mesh);
  EXPECT_NE(not_solid.note.find("\"open tray\" is an open mesh"), std::string::npos)
      << not_solid.note;
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
  part.surface->file_mesh = mesh;
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
