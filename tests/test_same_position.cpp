// Welding by position (geometry/same_position.h) against a scan of every
// earlier column.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "geometry/same_position.h"

using namespace pd;

namespace {

// Triangles of the corners c as STL stores them: each triangle its own three
// vertices, `spare` more columns at the end (set by the caller).
Mesh soup_of_corners(const std::vector<Vec3>& c, const std::vector<std::array<int, 3>>& faces,
                     int spare = 0) {
  const int n = static_cast<int>(faces.size());
  Mesh m;
  m.vertices.resize(3, 3 * n + spare);
  m.vertices.setZero();
  m.triangles.resize(3, n);
  for (int t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      m.vertices.col(3 * t + k) = c[size_t(faces[size_t(t)][size_t(k)])];
      m.triangles(k, t) = 3 * t + k;
    }
  return m;
}

const std::vector<Vec3> kTetrahedronCorners = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0),
                                               Vec3(0, 0, 1)};

}  // namespace

TEST(SamePosition, BoundaryEdgesAreThoseOfAnOddNumberOfTriangles) {
  // A tetrahedron as STL stores it (each triangle its own corners): closed.
  const Mesh m = soup_of_corners(kTetrahedronCorners, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
  EXPECT_EQ(boundary_edges(m), 0);
  Mesh open = m;  // one face missing: its three edges are the boundary
  open.triangles.conservativeResize(3, 3);
  EXPECT_EQ(boundary_edges(open), 3);
  EXPECT_EQ(boundary_edges(Mesh{m.vertices, Triangles(3, 0)}), 0);  // a point cloud
}

TEST(SamePosition, AGridSheetsBoundaryIsItsRim) {
  // A k × k sheet of quads written as STL writes it (every triangle its own
  // corners, in float32 far from the origin): 4k rim edges; each triangle
  // written twice more (a doubled body) leaves every parity as it was.
  for (int k : {1, 7, 40}) {
    Mesh m;
    std::vector<Vec3> corners;
    auto at = [&](int i, int j) {
      return Vec3(double(float(20000.0 + 0.1 * i)), double(float(-300.0 + 0.1 * j)), 5.0);
    };
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j)
        for (const Vec3& c :
             {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)})
          corners.push_back(c);
    m.vertices.resize(3, static_cast<Eigen::Index>(corners.size()));
    for (size_t i = 0; i < corners.size(); ++i) m.vertices.col(Eigen::Index(i)) = corners[i];
    const Eigen::Index t = m.vertices.cols() / 3;
    m.triangles.resize(3, 3 * t);
    for (Eigen::Index c = 0; c < 3 * t; ++c)
      for (int r = 0; r < 3; ++r) m.triangles(r, c) = static_cast<int>(3 * (c % t) + r);
    const std::vector<int> first = first_at_same_position(m.vertices);
    EXPECT_EQ(boundary_edges(m, first), 4 * k) << k;
    EXPECT_EQ(distinct_positions(m.vertices, first).cols(), (k + 1) * (k + 1)) << k;
  }
}

TEST(SamePosition, EveryColumnPointsAtTheFirstEqualOne) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> pick(0, 5);
  for (int round = 0; round < 20; ++round) {
    // Few distinct values, so many repeats; −0 beside 0, a NaN and an infinity.
    const double values[] = {0.0, -0.0, 1.0, 1e300, 30000.125f, -2.5};
    Points p(3, 60 + round);
    for (long i = 0; i < p.cols(); ++i)
      for (int k = 0; k < 3; ++k) p(k, i) = values[pick(rng)];
    p(1, 7) = NAN;
    p(2, 11) = INFINITY;
    p.col(12) = p.col(11);  // equal, but not finite: each its own
    const std::vector<int> first = first_at_same_position(p);
    ASSERT_EQ(first.size(), static_cast<size_t>(p.cols()));
    for (long i = 0; i < p.cols(); ++i) {
      int expected = static_cast<int>(i);
      if (p.col(i).allFinite())
        for (long j = 0; j < i; ++j)
          if (p.col(j).allFinite() && p(0, j) == p(0, i) && p(1, j) == p(1, i) &&
              p(2, j) == p(2, i)) {
            expected = static_cast<int>(j);
            break;
          }
      EXPECT_EQ(first[i], expected) << "round " << round << " column " << i;
    }
    // The distinct positions: the columns that are their own first, in order.
    const Points d = distinct_positions(p, first);
    Eigen::Index k = 0;
    for (long i = 0; i < p.cols(); ++i)
      if (first[i] == i) {
        ASSERT_LT(k, d.cols());
        EXPECT_TRUE(d.col(k++).cwiseEqual(p.col(i)).count() == 3 || !p.col(i).allFinite());
      }
    EXPECT_EQ(k, d.cols());
  }
  EXPECT_TRUE(first_at_same_position(Points(3, 0)).empty());
}

TEST(SamePosition, WeldedKeepsEveryTrianglesCornersWithEachPositionOnce) {
  // A tetrahedron as STL stores it, a needle (two corners at one position),
  // and a −0 that equals its 0; a column no triangle uses stays.
  Mesh m = soup_of_corners(kTetrahedronCorners,
                           {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {1, 1, 2}}, 1);
  m.vertices.col(3) = Vec3(-0.0, 0, 0);  // face 1's first corner: c[0]'s position
  m.vertices.col(15) = Vec3(7, 7, 7);    // used by no triangle
  const Mesh w = welded(m, first_at_same_position(m.vertices));
  ASSERT_EQ(w.triangles.cols(), m.triangles.cols());
  EXPECT_EQ(w.vertices.cols(), 5);  // the four corners, and (7, 7, 7)
  for (long t = 0; t < m.triangles.cols(); ++t)
    for (int k = 0; k < 3; ++k)
      EXPECT_TRUE(w.vertices.col(w.triangles(k, t)) == m.vertices.col(m.triangles(k, t)))
          << "triangle " << t << " corner " << k;
  for (long i = 0; i < w.vertices.cols(); ++i)
    for (long j = 0; j < i; ++j)
      EXPECT_FALSE(w.vertices.col(i) == w.vertices.col(j)) << i << " " << j;
  EXPECT_EQ(w.triangles(0, 4), w.triangles(1, 4));  // the needle stays one
}
