// The face axes (PreparedMesh::face_axes): a rotated block's axes are its
// edges, a washer's first axis is its normal, and the result is always a rotation.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "corpus/cad_shapes.h"
#include "geometry/mesh_intersect.h"
#include "random_rotation.h"

namespace pd {
namespace {

using pd_test::random_rotation;

Mesh rotated(Mesh m, const Eigen::Matrix3d& r, const Vec3& offset) {
  for (long k = 0; k < m.vertices.cols(); ++k)
    m.vertices.col(k) = r * Vec3(m.vertices.col(k)) + offset;
  return m;
}

void expect_rotation(const Eigen::Matrix3d& r) {
  EXPECT_TRUE((r.transpose() * r).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
  EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
}

TEST(FaceAxes, ARotatedBlocksAxesAreItsEdges) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Matrix3d turn = random_rotation(rng);
    const Mesh block = rotated(shapes::box({0, 0, 0}, {30, 20, 10}), turn, Vec3(21000, -4000, 900));
    const Eigen::Matrix3d r = PreparedMesh(block).face_axes();
    expect_rotation(r);
    // The largest faces (30 × 20) first, then the 30 × 10 ones.
    EXPECT_NEAR(std::abs(r.col(0).dot(turn.col(2))), 1.0, 1e-9) << "trial " << trial;
    EXPECT_NEAR(std::abs(r.col(1).dot(turn.col(1))), 1.0, 1e-9) << "trial " << trial;
    EXPECT_NEAR(std::abs(r.col(2).dot(turn.col(0))), 1.0, 1e-9) << "trial " << trial;
  }
}

TEST(FaceAxes, AWashersFirstAxisIsItsNormalAndAPinsAxisIsOneOfThem) {
  std::mt19937 rng(9);
  const Eigen::Matrix3d turn = random_rotation(rng);
  const Mesh washer =
      rotated(shapes::revolution({{5, 0}, {8, 0}, {8, 1.5}, {5, 1.5}}, 64), turn, Vec3::Zero());
  EXPECT_NEAR(std::abs(PreparedMesh(washer).face_axes().col(0).dot(turn.col(2))), 1.0, 1e-9);
  // A pin: its end caps or its facets come first, and either way its axis is
  // one of the three (its facets run along the boxes' sides).
  const Mesh pin =
      rotated(shapes::revolution({{0, 0}, {3, 0}, {3, 40}, {0, 40}}, 64), turn, Vec3::Zero());
  const Eigen::Matrix3d r = PreparedMesh(pin).face_axes();
  expect_rotation(r);
  EXPECT_NEAR((r.transpose() * turn.col(2)).cwiseAbs().maxCoeff(), 1.0, 1e-9);
}

TEST(FaceAxes, IsARotationForAnyTriangleSoup) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 20; ++trial) {
    Mesh m;
    m.vertices.resize(3, 30);
    m.triangles.resize(3, 10);
    for (long k = 0; k < 30; ++k) m.vertices.col(k) = Vec3(u(rng), u(rng), u(rng));
    for (long t = 0; t < 10; ++t) m.triangles.col(t) = Eigen::Vector3i(3 * t, 3 * t + 1, 3 * t + 2);
    expect_rotation(PreparedMesh(m).face_axes());
  }
}

}  // namespace
}  // namespace pd
