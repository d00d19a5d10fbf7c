// Seeded generators of polytope pairs, shared by the tests and the benchmark (pdbench).
#pragma once

#include <Eigen/Geometry>

#include "geometry/hull.h"
#include "solve/exact.h"
#include "solve/mlsl.h"
#include "solve/objective.h"

namespace pd::testgen {

/// n points uniform in a ball, hulled.
inline Points ball_polytope(SphereSampler& r, int n, const Vec3& centre, double radius) {
  Points p(3, n);
  for (int i = 0; i < n; ++i) p.col(i) = centre + radius * std::cbrt(r.uniform()) * r.direction();
  return convex_hull(p).vertices;
}

/// m points on a sphere (a Fibonacci lattice, slightly jittered so no four are coplanar).
inline Points sphere_polytope(SphereSampler& r, int m, const Vec3& centre, double radius) {
  Points p(3, m);
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < m; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / m, rho = std::sqrt(1.0 - z * z);
    const double t = golden * i + 1e-3 * r.uniform();
    p.col(i) = centre + radius * Vec3(rho * std::cos(t), rho * std::sin(t), z);
  }
  return p;
}

struct PairCase {
  Points a, b;
};

/// n points on a random ellipsoid's surface (semi-axes in [radius/2, radius],
/// random orientation): every point is a hull vertex, so the class is exactly n.
inline Points ellipsoid_polytope(SphereSampler& r, int n, const Vec3& centre, double radius) {
  const Vec3 axes(radius * (0.5 + 0.5 * r.uniform()), radius * (0.5 + 0.5 * r.uniform()),
                  radius * (0.5 + 0.5 * r.uniform()));
  Eigen::Quaterniond rot(r.uniform() + 0.1, r.uniform() - 0.5, r.uniform() - 0.5,
                         r.uniform() - 0.5);
  const Eigen::Matrix3d m = rot.normalized().toRotationMatrix() * axes.asDiagonal();
  Points p(3, n);
  for (int i = 0; i < n; ++i) p.col(i) = centre + m * r.direction();
  return p;
}

/// Draws from `make` until the pair overlaps (the exact reference says so).
template <class Make>
PairCase overlapping(SphereSampler& r, Make make) {
  for (;;) {
    PairCase c = make(r);
    const PairProblem pr(c.a, c.b);
    if (exact_depth(pr.p(), pr.q()).depth > 1e-6) return c;
  }
}

/// Like the paper's problems: 5–15 vertices, sizes 10–100 (may be separated).
inline PairCase paper_like_any(SphereSampler& r) {
  const double ra = 10 + 40 * r.uniform(), rb = 10 + 40 * r.uniform();
  const int na = 5 + static_cast<int>(11 * r.uniform()),
            nb = 5 + static_cast<int>(11 * r.uniform());
  const Vec3 c = r.direction() * (ra + rb) * 0.5 * r.uniform();
  return {ball_polytope(r, std::max(na, 5), Vec3::Zero(), ra),
          ball_polytope(r, std::max(nb, 5), c, rb)};
}
inline PairCase paper_like(SphereSampler& r) {
  return overlapping(r, paper_like_any);
}

/// Like the paper's problem 14: ~100 vertices, coordinates in the thousands.
inline PairCase large_coordinates(SphereSampler& r, int n = 100) {
  const Vec3 base(3000 + 2000 * r.uniform(), -4000 * r.uniform(), 2000 * r.uniform());
  const double ra = 20000 + 10000 * r.uniform(), rb = 20000 + 10000 * r.uniform();
  const Vec3 c = base + r.direction() * (ra + rb) * 0.5 * r.uniform();
  return {ball_polytope(r, n, base, ra), ball_polytope(r, n, c, rb)};
}

/// A vertex-count class: n + n points on two random ellipsoids of size 10–100,
/// overlapping by a random fraction of their size.
inline PairCase vertex_class(SphereSampler& r, int n) {
  return overlapping(r, [n](SphereSampler& g) {
    const double ra = 10 + 90 * g.uniform(), rb = 10 + 90 * g.uniform();
    const Vec3 c = g.direction() * (ra + rb) * 0.6 * g.uniform();
    return PairCase{ellipsoid_polytope(g, n, Vec3::Zero(), ra), ellipsoid_polytope(g, n, c, rb)};
  });
}

/// Zhou et al.'s spheres: m points, radius 10, at (0,0,0) and (20,10,30), the
/// second moved along the line of centres into overlap.
inline PairCase zhou_spheres(SphereSampler& r, int m) {
  const Vec3 c2(20, 10, 30);
  const double d = 2.0 + 16.0 * r.uniform();  // centre distance in (2, 18): overlapping
  return {sphere_polytope(r, m, Vec3::Zero(), 10), sphere_polytope(r, m, c2.normalized() * d, 10)};
}

/// The hard cases of tests/test_hard_cases.cpp as a benchmark set (issue 29):
/// case k % 8 of identical cubes, cubes overlapping by 1e-9 of their size,
/// coplanar faces with tied optima, a cube inside a cube, 1000×1000×1 plates
/// overlapping by 0.01, a flat square in a cube, two identical random
/// polytopes, a 1 mm pin in a 10 m panel; rotated at random when k / 8 is odd.
inline PairCase hard_case(SphereSampler& r, int k) {
  auto box = [](const Vec3& lo, const Vec3& hi) {
    Points p(3, 8);
    for (int c = 0; c < 8; ++c)
      p.col(c) = Vec3(c & 1 ? hi.x() : lo.x(), c & 2 ? hi.y() : lo.y(), c & 4 ? hi.z() : lo.z());
    return p;
  };
  const Vec3 o = Vec3::Zero(), one = Vec3::Ones();
  PairCase c;
  switch (k % 8) {
    case 0:
      c = {box(o, one), box(o, one)};
      break;
    case 1:
      c = {box(o, one), box(Vec3(1 - 1e-9, 0, 0), Vec3(2 - 1e-9, 1, 1))};
      break;
    case 2:
      c = {box(o, one), box(Vec3(0.5, 0.5, 0), Vec3(1.5, 1.5, 1))};
      break;
    case 3:
      c = {box(o, one), box(Vec3::Constant(0.4), Vec3::Constant(0.6))};
      break;
    case 4:
      c = {box(o, Vec3(1000, 1000, 1)), box(Vec3(0, 0, 0.99), Vec3(1000, 1000, 1.99))};
      break;
    case 5: {
      Points sq(3, 4);
      sq << 0.2, 0.8, 0.8, 0.2, 0.2, 0.2, 0.8, 0.8, 0.5, 0.5, 0.5, 0.5;
      c = {box(o, one), sq};
      break;
    }
    case 6: {
      const Points p = ball_polytope(r, 40, Vec3(3, 4, 5), 10);
      c = {p, p};
      break;
    }
    default: {
      Points pin(3, 48);
      for (int s = 0; s < 24; ++s) {
        const double t = 2 * M_PI * s / 24;
        pin.col(s) = Vec3(5000 + 0.5 * std::cos(t), 5000 + 0.5 * std::sin(t), 4.9);
        pin.col(24 + s) = Vec3(5000 + 0.5 * std::cos(t), 5000 + 0.5 * std::sin(t), 24.9);
      }
      c = {box(o, Vec3(10000, 10000, 5)), pin};
    }
  }
  if ((k / 8) % 2) {
    const Eigen::Matrix3d rot =
        Eigen::AngleAxisd(2 * M_PI * r.uniform(), r.direction()).toRotationMatrix();
    c.a = rot * c.a;
    c.b = rot * c.b;
  }
  return c;
}

}  // namespace pd::testgen
