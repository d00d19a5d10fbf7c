// One reentrant qhull run (geometry/qhull_session.h): a tetrahedron with a
// point inside has 4 facets and 4 vertices, the inner point not among them; a
// square in 2-D likewise; flat input is refused with qhull's message; two
// sessions alive at once keep their own results.
#include <gtest/gtest.h>

#include <vector>

#include "geometry/qhull_session.h"

using namespace pd;

namespace {

// The regular tetrahedron's corners of the cube [−1, 1]³, then its centre.
const std::vector<double> kTetrahedronPoints = {1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1, 0, 0, 0};

}  // namespace

TEST(QhullSession, ATetrahedronHasFourFacetsAndItsCornersAsVertices) {
  QhullSession s(3, kTetrahedronPoints, "qhull");
  ASSERT_TRUE(s.ok()) << s.error();
  EXPECT_TRUE(s.error().empty());
  EXPECT_EQ(s.qh()->num_facets, 4);
  EXPECT_EQ(s.qh()->num_vertices, 4);
  EXPECT_EQ(s.vertex_ids(), (std::vector<int>{0, 1, 2, 3}));
}

TEST(QhullSession, ASquareIn2DHasFourEdges) {
  QhullSession s(2, {0, 0, 2, 0, 2, 2, 0, 2, 1, 1, 1, 0}, "qhull");
  ASSERT_TRUE(s.ok()) << s.error();
  EXPECT_EQ(s.qh()->num_facets, 4);
  EXPECT_EQ(s.vertex_ids(), (std::vector<int>{0, 1, 2, 3}));
}

TEST(QhullSession, FlatInputIsRefusedWithQhullsMessage) {
  // Four points in the plane z = 0: no 3-D simplex to start from.
  QhullSession s(3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, "qhull");
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.error().find("QH6154"), std::string::npos) << s.error();
}

TEST(QhullSession, SessionsAliveAtOnceKeepTheirOwnResults) {
  QhullSession tetra(3, kTetrahedronPoints, "qhull");
  std::vector<double> cube;
  for (int k = 0; k < 8; ++k)
    for (int bit : {1, 2, 4}) cube.push_back(k & bit ? 1.0 : -1.0);
  QhullSession box(3, cube, "qhull");
  ASSERT_TRUE(tetra.ok() && box.ok());
  EXPECT_EQ(tetra.vertex_ids(), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(box.vertex_ids(), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(tetra.qh()->num_facets, 4);
  EXPECT_EQ(box.qh()->num_facets, 6);  // merged coplanar facets: the cube's faces
}
