// The triangle tree against a scan of every triangle: nearest points on random
// triangle soups (slivers, far from the origin) and a CAD-like cylinder, with
// and without a starting face, and the triangles that meet a box.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <random>
#include <set>

#include "corpus/cad_shapes.h"
#include "geometry/triangle_tree.h"

namespace pd {
namespace {

using Triangles3 = std::vector<std::array<Vec3, 3>>;

TriangleTree::Nearest scan(const Triangles3& t, const Vec3& p) {
  TriangleTree::Nearest best;
  for (size_t i = 0; i < t.size(); ++i) {
    const Vec3 q = closest_on_triangle(p, t[i][0], t[i][1], t[i][2]);
    if ((q - p).squaredNorm() < best.squared_distance)
      best = {q, static_cast<int>(i), (q - p).squaredNorm()};
  }
  return best;
}

// The tree's answer is as near as the scan's (its face may differ on a tie)
// and is the nearest point of the face it names.
void expect_nearest(const TriangleTree& tree, const Triangles3& t, const Vec3& p, int start) {
  const TriangleTree::Nearest want = scan(t, p), got = tree.nearest(p, start);
  ASSERT_GE(got.face, 0);
  const double scale = 1 + p.cwiseAbs().maxCoeff();
  EXPECT_NEAR(std::sqrt(got.squared_distance), std::sqrt(want.squared_distance), 1e-12 * scale);
  const auto& f = t[got.face];
  EXPECT_LE((got.point - closest_on_triangle(p, f[0], f[1], f[2])).norm(), 1e-12 * scale);
}

TEST(TriangleTree, EqualsAScanOfEveryTriangle) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const double offset : {0.0, 5e4}) {  // far from the origin, as CAD exports are
    const Vec3 o = Vec3::Constant(offset);
    Triangles3 t;
    for (int i = 0; i < 500; ++i) {
      const Vec3 a = o + 10 * Vec3(u(rng), u(rng), u(rng));
      const Vec3 along = Vec3(u(rng), u(rng), u(rng)) * (i % 3 == 0 ? 8.0 : 1.0);
      const Vec3 across = Vec3(u(rng), u(rng), u(rng)) * (i % 3 == 0 ? 1e-3 : 1.0);  // slivers
      t.push_back({a, a + along, a + along * (i % 7 == 0 ? 0.5 : 0.3) + across});
    }
    const TriangleTree tree(t);
    for (int k = 0; k < 2000; ++k) {
      const Vec3 p = o + 14 * Vec3(u(rng), u(rng), u(rng));
      expect_nearest(tree, t, p, k % 2 ? static_cast<int>(rng() % t.size()) : -1);
    }
  }
}

TEST(TriangleTree, FindsTheFacetOfACylinderNearAPointOnIt) {
  const Mesh m = shapes::cylinder({0, 0}, 3.0, 0.0, 40.0, 96);
  Triangles3 t;
  for (long f = 0; f < m.triangles.cols(); ++f)
    t.push_back({m.vertices.col(m.triangles(0, f)), m.vertices.col(m.triangles(1, f)),
                 m.vertices.col(m.triangles(2, f))});
  const TriangleTree tree(t);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI), z(-1, 41), r(2.9, 3.1);
  for (int k = 0; k < 2000; ++k) {
    const double a = angle(rng), rr = r(rng);
    expect_nearest(tree, t, Vec3(rr * std::cos(a), rr * std::sin(a), z(rng)), -1);
  }
}

// Whether triangle t meets the closed box [lo, hi], by separating axes (the
// box's three, the triangle's normal, and the nine edge crossings).
bool triangle_meets_box(const std::array<Vec3, 3>& t, const Vec3& lo, const Vec3& hi) {
  const Vec3 c = (lo + hi) / 2, e = (hi - lo) / 2;
  const std::array<Vec3, 3> v{t[0] - c, t[1] - c, t[2] - c};
  for (int k = 0; k < 3; ++k)  // the box's own axes first: most triangles are far
    if (std::min({v[0][k], v[1][k], v[2][k]}) > e[k] ||
        std::max({v[0][k], v[1][k], v[2][k]}) < -e[k])
      return false;
  const std::array<Vec3, 3> edge{v[1] - v[0], v[2] - v[1], v[0] - v[2]};
  std::array<Vec3, 13> axes;
  axes[0] = Vec3::UnitX(), axes[1] = Vec3::UnitY(), axes[2] = Vec3::UnitZ();
  axes[3] = edge[0].cross(edge[1]);
  for (int g = 0; g < 3; ++g)
    for (int k = 0; k < 3; ++k) axes[4 + 3 * g + k] = edge[g].cross(Vec3::Unit(k));
  for (const Vec3& u : axes) {
    const double r = e.dot(u.cwiseAbs());
    const double lo_t = std::min({v[0].dot(u), v[1].dot(u), v[2].dot(u)}),
                 hi_t = std::max({v[0].dot(u), v[1].dot(u), v[2].dot(u)});
    if (lo_t > r || hi_t < -r) return false;
  }
  return true;
}

// A box of the world's axes (R the identity): every triangle that meets it is
// listed, in order. A tree in the world's axes (a wide box of them added to
// the soup) lists exactly the triangles whose boxes meet it, up to rounding;
// a turned one (the widest random face is oblique), and the same soup far
// from the origin, may list more.
TEST(TriangleTree, ListsEveryTriangleThatMeetsABoxInOrder) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  Triangles3 t;
  for (int i = 0; i < 800; ++i) {
    const Vec3 a = 10 * Vec3(u(rng), u(rng), u(rng));
    t.push_back({a, a + 3 * Vec3(u(rng), u(rng), u(rng)), a + Vec3(u(rng), u(rng), u(rng))});
  }
  t.push_back({Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(3, 1, 0)});  // touches the box below at x = 2
  const size_t touching = t.size() - 1;
  Triangles3 with_world_box = t;
  const Mesh w = shapes::box(Vec3(-40, -40, 30), Vec3(40, 40, 50));
  for (long f = 0; f < w.triangles.cols(); ++f)
    with_world_box.push_back({w.vertices.col(w.triangles(0, f)), w.vertices.col(w.triangles(1, f)),
                              w.vertices.col(w.triangles(2, f))});
  int checked_touch = 0;
  for (const int variant : {0, 1, 2}) {
    Triangles3 moved = variant == 0 ? with_world_box : t;
    const Vec3 offset = variant == 2 ? Vec3(3.1e4, -2.2e4, 7.5e3) : Vec3::Zero();
    for (auto& tri : moved)
      for (Vec3& v : tri) v += offset;
    const TriangleTree tree(moved);
    EXPECT_EQ(tree.rotated(), variant != 0);
    for (int k = 0; k < 120; ++k) {
      Vec3 lo = 10 * Vec3(u(rng), u(rng), u(rng)),
           hi = lo + 4 * Vec3(u(rng), u(rng), u(rng)).cwiseAbs();
      if (k == 0) lo = Vec3(0, 0, -1), hi = Vec3(2, 1, 1);
      lo += offset, hi += offset;
      std::vector<int> got{-7};  // appended after what is there
      tree.in_turned_box(Eigen::Matrix3d::Identity(), Vec3::Zero(), lo, hi, got);
      ASSERT_EQ(got.front(), -7);
      got.erase(got.begin());
      EXPECT_TRUE(std::is_sorted(got.begin(), got.end()));
      for (size_t i = 0; i < moved.size(); ++i) {
        const auto& m = moved[i];
        const Vec3 a = m[0].cwiseMin(m[1]).cwiseMin(m[2]), b = m[0].cwiseMax(m[1]).cwiseMax(m[2]);
        const bool listed = std::binary_search(got.begin(), got.end(), static_cast<int>(i));
        const double hair = 1e-9;
        const bool box_near =
            ((a.array() - hair) <= hi.array()).all() && (lo.array() <= (b.array() + hair)).all();
        if (variant == 0 && !box_near) {
          EXPECT_FALSE(listed) << "box " << k << " triangle " << i;
        }
        if (box_near && triangle_meets_box(m, lo, hi)) {
          EXPECT_TRUE(listed) << "variant " << variant << " box " << k << " triangle " << i;
        }
        if (k == 0 && i == touching && offset.isZero()) checked_touch += listed;
      }
    }
  }
  EXPECT_EQ(checked_touch, 2);
}

// A segment through a point inside a triangle must reach that triangle,
// whatever its direction (oblique or along an axis, where the box test
// compares coordinates), and visits stop when the visitor says so.
TEST(TriangleTree, ASegmentVisitsEveryTriangleItPierces) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1, 1), w(0.05, 0.9);
  const Vec3 o(3.1e4, -7.7e3, 512.0);  // far from the origin
  Triangles3 t;
  for (int i = 0; i < 600; ++i) {
    const Vec3 a = o + 10 * Vec3(u(rng), u(rng), u(rng));
    t.push_back({a, a + 2 * Vec3(u(rng), u(rng), u(rng)), a + Vec3(u(rng), u(rng), u(rng))});
  }
  // As it is, the widest face sets an oblique frame; with a wide box of the
  // world's axes added, the boxes are the world's and axis segments are met
  // by comparisons.
  for (const bool square : {false, true}) {
    if (square) {
      const Mesh b = shapes::box(o + Vec3(-60, -60, 40), o + Vec3(60, 60, 80));
      for (long f = 0; f < b.triangles.cols(); ++f)
        t.push_back({b.vertices.col(b.triangles(0, f)), b.vertices.col(b.triangles(1, f)),
                     b.vertices.col(b.triangles(2, f))});
    }
    const TriangleTree tree(t);
    EXPECT_EQ(tree.rotated(), !square);
    for (int k = 0; k < 600; ++k) {
      const int i = static_cast<int>(rng() % 600);
      const double b1 = w(rng) / 2, b2 = w(rng) / 2;
      const Vec3 x = t[i][0] + b1 * (t[i][1] - t[i][0]) + b2 * (t[i][2] - t[i][0]);
      Vec3 d = Vec3(u(rng), u(rng), u(rng)).normalized();
      if (k % 2) d = Vec3::Unit(k % 3);  // along an axis
      bool seen = false;
      int visits = 0;
      tree.along_segment(x - 30 * d, x + 3 * w(rng) * d, [&](int id, const std::array<Vec3, 3>& c) {
        seen = seen || id == i;
        EXPECT_EQ(c, t[id]);
        ++visits;
        return false;
      });
      EXPECT_TRUE(seen) << k;
      EXPECT_LT(visits, 600) << k;  // the tree prunes
    }
    int visits = 0;
    EXPECT_TRUE(tree.along_segment(o - Vec3::Constant(20), o + Vec3::Constant(20),
                                   [&](int, const std::array<Vec3, 3>&) { return ++visits == 3; }));
    EXPECT_EQ(visits, 3);
  }
}

// A drilled board, its faces long slivers as CAD exporters write them, turned
// askew far from the origin: the tree takes the board's own axes, and its
// nearest points are a scan's.
TEST(TriangleTree, TakesTheFrameOfAPartPlacedAskew) {
  const Mesh plate = shapes::drilled_board(3, 1, 12.0, 1.6, 2.0, 48);
  const Eigen::Matrix3d r =
      (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()) * Eigen::AngleAxisd(-0.4, Vec3::UnitX()))
          .toRotationMatrix();
  const Vec3 far(3.6e4, 4.3e3, -2.7e4);
  Triangles3 flat, askew;
  for (long f = 0; f < plate.triangles.cols(); ++f) {
    std::array<Vec3, 3> a, b;
    for (int k = 0; k < 3; ++k) {
      a[k] = plate.vertices.col(plate.triangles(k, f));
      b[k] = r * a[k] + far;
    }
    flat.push_back(a), askew.push_back(b);
  }
  EXPECT_FALSE(TriangleTree(flat).rotated());
  const TriangleTree tree(askew);
  ASSERT_TRUE(tree.rotated());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> x(-2, 38), y(-2, 14), z(-1, 3);
  for (int k = 0; k < 2000; ++k)
    expect_nearest(tree, askew, r * Vec3(x(rng), y(rng), z(rng)) + far, k % 3 ? -1 : 0);
}

// A turned box lists every triangle that meets it: boxes in the tree's own
// axes (the region a part's frame holds) and in random ones, about an askew
// drilled board far from the origin.
TEST(TriangleTree, ListsEveryTriangleThatMeetsATurnedBox) {
  const Mesh board = shapes::drilled_board(3, 2, 10.0, 1.6, 3.0, 32);
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.9, Vec3(2, -1, 3).normalized()).toRotationMatrix();
  const Vec3 far(-2.4e4, 3.3e4, 9.1e3);
  Triangles3 t;
  for (long f = 0; f < board.triangles.cols(); ++f) {
    std::array<Vec3, 3> c;
    for (int k = 0; k < 3; ++k) c[k] = r * board.vertices.col(board.triangles(k, f)) + far;
    t.push_back(c);
  }
  const TriangleTree tree(t);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> x(-2, 32), y(-2, 22), z(-1, 3), size(0.05, 4);
  for (int k = 0; k < 120; ++k) {
    const Eigen::Matrix3d turn =
        k % 2 ? tree.axes()
              : Eigen::Matrix3d(
                    Eigen::AngleAxisd(6.3 * size(rng), Vec3(x(rng), y(rng), z(rng)).normalized()));
    const Vec3 origin = r * Vec3(x(rng), y(rng), z(rng)) + far;
    const Vec3 lo = -Vec3(size(rng), size(rng), size(rng)),
               hi = Vec3(size(rng), size(rng), size(rng));
    std::vector<int> got;
    tree.in_turned_box(turn, origin, lo, hi, got);
    EXPECT_TRUE(std::is_sorted(got.begin(), got.end()));
    for (size_t i = 0; i < t.size(); ++i) {
      std::array<Vec3, 3> local;  // the triangle in the box's frame
      for (int c = 0; c < 3; ++c) local[c] = turn.transpose() * (t[i][c] - origin);
      if (triangle_meets_box(local, lo, hi)) {
        EXPECT_TRUE(std::binary_search(got.begin(), got.end(), static_cast<int>(i)))
            << "box " << k << " triangle " << i;
      }
    }
  }
}

TEST(TriangleTree, StopsListingPastTheLimit) {
  Triangles3 t;
  for (int i = 0; i < 100; ++i) t.push_back({Vec3(i, 0, 0), Vec3(i + 1, 0, 0), Vec3(i, 1, 0)});
  const TriangleTree tree(t);
  std::vector<int> all, few;
  tree.in_turned_box(Eigen::Matrix3d::Identity(), Vec3::Zero(), Vec3(-1, -1, -1), Vec3(200, 2, 1),
                     all, 100);
  EXPECT_EQ(all.size(), 100u);  // exactly the limit: every one, in order
  EXPECT_TRUE(std::is_sorted(all.begin(), all.end()));
  tree.in_turned_box(Eigen::Matrix3d::Identity(), Vec3::Zero(), Vec3(-1, -1, -1), Vec3(200, 2, 1),
                     few, 10);
  EXPECT_EQ(few.size(), 11u);  // past it: one more than the limit says so
}

// Two askew boards far from the origin, each in its own frame, and small
// triangles hung from the first board's corners: walking both trees together
// visits every pair of triangles that share a point (a corner touching a face
// is where rounding would drop a pair), prunes the rest, and stops when told.
TEST(TriangleTree, WalkingTwoTreesVisitsEveryPairThatShareAPoint) {
  const Vec3 far(2.9e4, -1.3e4, 6.1e3);
  const auto placed = [&](const Mesh& m, const Eigen::Matrix3d& r, const Vec3& shift) {
    Triangles3 t;
    for (long f = 0; f < m.triangles.cols(); ++f) {
      std::array<Vec3, 3> c;
      for (int k = 0; k < 3; ++k) c[k] = r * (m.vertices.col(m.triangles(k, f)) + shift) + far;
      t.push_back(c);
    }
    return t;
  };
  const Eigen::Matrix3d r1 = Eigen::AngleAxisd(0.8, Vec3(1, -2, 3).normalized()).toRotationMatrix(),
                        r2 = Eigen::AngleAxisd(-1.1, Vec3(3, 1, 1).normalized()).toRotationMatrix();
  const Triangles3 a = placed(shapes::drilled_board(3, 2, 10.0, 1.6, 3.0, 32), r1, Vec3::Zero());
  Triangles3 b = placed(shapes::drilled_board(2, 2, 8.0, 2.0, 2.5, 24), r2, Vec3(5, 3, -1));
  const size_t board_b = b.size();
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 300; ++k) {  // a corner exactly at a corner of a
    const Vec3 v = a[rng() % a.size()][rng() % 3];
    b.push_back(
        {v, v + 0.3 * Vec3(u(rng), u(rng), u(rng)), v + 0.3 * Vec3(u(rng), u(rng), u(rng))});
  }
  const TriangleTree ta(a), tb(b);
  ASSERT_TRUE(ta.rotated());
  ASSERT_TRUE(tb.rotated());
  std::set<std::pair<int, int>> seen;
  EXPECT_FALSE(TriangleTree::pairs_near(ta, tb, [&](int i, int j) {
    EXPECT_TRUE(seen.insert({i, j}).second) << "pair visited twice";
    return false;
  }));
  for (size_t j = board_b; j < b.size(); ++j)
    for (size_t i = 0; i < a.size(); ++i)
      if (std::find(a[i].begin(), a[i].end(), b[j][0]) != a[i].end()) {
        EXPECT_TRUE(seen.count({int(i), int(j)})) << i << " " << j;
      }
  EXPECT_LT(seen.size(), a.size() * b.size() / 20);  // the trees prune
  int visits = 0;
  EXPECT_TRUE(TriangleTree::pairs_near(ta, tb, [&](int, int) { return ++visits == 5; }));
  EXPECT_EQ(visits, 5);
}

TEST(TriangleTree, NoTrianglesNoNearest) {
  const TriangleTree tree{Triangles3{}};
  EXPECT_TRUE(tree.empty());
  EXPECT_EQ(tree.nearest(Vec3::Zero()).face, -1);
}

TEST(TriangleTree, ACornerRegionGivesTheCorner) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_EQ(closest_on_triangle(Vec3(-1, -1, 2), a, b, c), a);
  EXPECT_EQ(closest_on_triangle(Vec3(3, -1, 0), a, b, c), b);
  EXPECT_TRUE(closest_on_triangle(Vec3(0.2, 0.2, 5), a, b, c).isApprox(Vec3(0.2, 0.2, 0)));
  EXPECT_TRUE(closest_on_triangle(Vec3(1, 1, 0), a, b, c).isApprox(Vec3(0.5, 0.5, 0)));
}

}  // namespace
}  // namespace pd
