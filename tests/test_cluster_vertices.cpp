// Vertex clustering (cluster_vertices.cpp): vertices merged per grid cell at
// their mean, collapsed and repeated triangles dropped.
#include <gtest/gtest.h>

#include "geometry/cluster_vertices.h"

using namespace pd;

TEST(ClusterVertices, NearVerticesMergeAndCollapsedTrianglesGo) {
  Mesh m;
  m.vertices.resize(3, 5);
  m.vertices << 0, 10, 0, 0.01, 10,  //
      0, 0, 10, 0.02, 0.03,          //
      0, 0, 0, 0, 0;
  m.triangles.resize(3, 4);
  m.triangles << 0, 3, 0, 0,  //
      1, 4, 4, 3,             //
      2, 2, 2, 1;
  // 10 cells along the longest side (10): cells of 1. Vertices 0, 3 share a
  // cell, so do 1, 4.
  const Mesh c = cluster_vertices(m, 10);
  ASSERT_EQ(c.vertices.cols(), 3);
  // The first cell's vertex is the mean of its members.
  EXPECT_NEAR((c.vertices.col(0) - Vec3(0.005, 0.01, 0)).norm(), 0.0, 1e-15);
  // Triangles (0,1,2), (3,4,2) and (0,4,2) are one; (0,3,1) collapsed.
  ASSERT_EQ(c.triangles.cols(), 1);
  EXPECT_EQ(c.triangles.col(0), Eigen::Vector3i(0, 1, 2));
  // A finer grid keeps every vertex apart, and every triangle that is one.
  const Mesh fine = cluster_vertices(m, 10000);
  EXPECT_EQ(fine.vertices.cols(), 5);
  EXPECT_EQ(fine.triangles.cols(), 4);
  EXPECT_EQ(cluster_vertices(Mesh{}, 10).vertices.cols(), 0);
}
