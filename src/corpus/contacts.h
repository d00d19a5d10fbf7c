// Seeded contact pairs as CAD produces them (issue 12), shared by pdbench and the
// tests: faces resting on faces, components seated on boards, tessellated shafts
// in bores and balls in sockets (exact fit, clearance, interference), parts a hair
// apart. Each pair is also drawn rotated, and rotated at x ≈ 20,000 mm with its
// coordinates rounded to float32 as a mesh file would store them.
//
// A bore or a socket is not convex; its convex pieces (what a decomposition gives
// and what the solver sees) each hold one facet of the tessellated hole. A piece
// here is that facet extruded outwards, so a pair is "shaft against one piece".
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "corpus/generators.h"

namespace pd::testgen {

/// How a contact pair is placed in the world.
enum class Placement { kAxes, kRotated, kFloat32Far };

/// A rounded-rectangle prism: n >= 8 vertices (n/2 around the outline, top and
/// bottom), half extents hx, hy, from z0 to z1. n = 8 is a box.
inline Points rounded_prism(int n, double hx, double hy, double z0, double z1, double corner) {
  const int ring = std::max(4, n / 2);
  Points p(3, 2 * ring);
  if (ring == 4) {
    const double x[4] = {-hx, hx, hx, -hx}, y[4] = {-hy, -hy, hy, hy};
    for (int k = 0; k < 4; ++k) {
      p.col(k) = Vec3(x[k], y[k], z0);
      p.col(4 + k) = Vec3(x[k], y[k], z1);
    }
    return p;
  }
  // ring/4 points on each quarter circle of radius `corner` at the four corners.
  const int per = ring / 4, extra = ring - 4 * per;
  int k = 0;
  for (int c = 0; c < 4; ++c) {
    const double sx = (c == 0 || c == 3) ? 1 : -1, sy = c < 2 ? 1 : -1;
    const int cnt = per + (c < extra ? 1 : 0);
    for (int i = 0; i < cnt; ++i) {
      const double t = c * M_PI / 2 + (cnt == 1 ? 0.25 : double(i) / (cnt - 1)) * M_PI / 2;
      const Vec3 xy(sx * (hx - corner) + corner * std::cos(t),
                    sy * (hy - corner) + corner * std::sin(t), 0);
      p.col(k) = Vec3(xy.x(), xy.y(), z0);
      p.col(ring + k) = Vec3(xy.x(), xy.y(), z1);
      ++k;
    }
  }
  return p;
}

/// A k-gon prism along z (radius r, from z0 to z1), the first vertex at angle a0.
inline Points ngon_prism(int k, double r, double z0, double z1, double a0) {
  Points p(3, 2 * k);
  for (int i = 0; i < k; ++i) {
    const double t = a0 + 2 * M_PI * i / k;
    p.col(i) = Vec3(r * std::cos(t), r * std::sin(t), z0);
    p.col(k + i) = Vec3(r * std::cos(t), r * std::sin(t), z1);
  }
  return p;
}

/// Places a pair: as generated, rotated about a random axis, or rotated and moved
/// to x ≈ 20,000 mm with every coordinate rounded to float32.
inline PairCase place(SphereSampler& r, PairCase c, Placement where) {
  if (where == Placement::kAxes) return c;
  const Eigen::Matrix3d rot =
      Eigen::AngleAxisd(2 * M_PI * r.uniform(), r.direction()).toRotationMatrix();
  const Vec3 shift = where == Placement::kFloat32Far
                         ? Vec3(20000 + 500 * r.uniform(), 300 * r.uniform(), 100 * r.uniform())
                         : Vec3::Zero();
  for (Points* x : {&c.a, &c.b}) {
    *x = (rot * *x).colwise() + shift;
    if (where == Placement::kFloat32Far) *x = x->cast<float>().cast<double>();
  }
  return c;
}

/// Face on face: a plate of n vertices resting on another (touching), the upper
/// one smaller and placed anywhere on the lower one's top face.
inline PairCase plates_touching(SphereSampler& r, int n) {
  const double hx = 20 + 80 * r.uniform(), hy = 20 + 80 * r.uniform(), t = 1 + 10 * r.uniform();
  const double ux = hx * (0.2 + 0.6 * r.uniform()), uy = hy * (0.2 + 0.6 * r.uniform());
  Points b = rounded_prism(n, ux, uy, t, t + 1 + 20 * r.uniform(), 0.2 * std::min(ux, uy));
  b.colwise() += Vec3((hx - ux) * (2 * r.uniform() - 1), (hy - uy) * (2 * r.uniform() - 1), 0);
  return {rounded_prism(n, hx, hy, 0, t, 0.2 * std::min(hx, hy)), b};
}

/// A component (a box, 8 vertices) seated on a board of n vertices.
inline PairCase seated_component(SphereSampler& r, int n) {
  const double hx = 50 + 100 * r.uniform(), hy = 50 + 100 * r.uniform(), t = 1.6;
  const double cx = 1 + 10 * r.uniform(), cy = 1 + 10 * r.uniform();
  Points comp = rounded_prism(8, cx, cy, t, t + 0.5 + 5 * r.uniform(), 0);
  comp.colwise() +=
      Vec3((hx - cx - 5) * (2 * r.uniform() - 1), (hy - cy - 5) * (2 * r.uniform() - 1), 0);
  return {rounded_prism(n, hx, hy, 0, t, 5), comp};
}

/// Fits of a shaft in its bore, a ball in its socket: radius of the hole minus
/// radius of the part (0.05 clearance, exact, 0.05 interference).
inline double fit_allowance(int k) {
  const double fits[3] = {0.05, 0.0, -0.05};
  return fits[k % 3];
}

/// A k-segment shaft (radius 10) in a k-segment bore with `allowance` (hole radius
/// minus shaft radius): the shaft against the bore's piece that holds one bore
/// facet (8 vertices). The two tessellations are rotated against each other at random.
inline PairCase shaft_in_bore(SphereSampler& r, int k, double allowance) {
  const double rs = 10, rb = rs + allowance, len = 30 + 30 * r.uniform();
  const double a0 = 2 * M_PI * r.uniform();
  const Points shaft = ngon_prism(k, rs, -len / 2, len / 2, a0 + 2 * M_PI / k * r.uniform());
  const double t0 = a0 + 2 * M_PI * std::floor(k * r.uniform()) / k, t1 = t0 + 2 * M_PI / k;
  const double depth = 5, half = 10 + 10 * r.uniform();
  Points piece(3, 8);
  int c = 0;
  for (double rad : {rb, rb + depth})
    for (double t : {t0, t1})
      for (double z : {-half, half}) piece.col(c++) = Vec3(rad * std::cos(t), rad * std::sin(t), z);
  return {piece, shaft};
}

/// A ball of m vertices (radius 10) in a socket of the same tessellation with
/// `allowance`: the ball against the socket's piece that holds one socket
/// triangle, extruded outwards (6 vertices).
inline PairCase ball_in_socket(SphereSampler& r, int m, double allowance) {
  const double rb = 10, rs = rb + allowance;
  const Points ball = sphere_polytope(r, m, Vec3::Zero(), rb);
  // The socket's tessellation: the same lattice, rotated at random, hulled.
  const Eigen::Matrix3d rot =
      Eigen::AngleAxisd(2 * M_PI * r.uniform(), r.direction()).toRotationMatrix();
  const Points socket = rot * sphere_polytope(r, m, Vec3::Zero(), rs);
  HullFacets f;
  hull_facets(socket, f);
  // A triangle of the lower half (where a ball rests), chosen at random.
  std::vector<size_t> lower;
  for (size_t t = 0; t < f.normals.size(); ++t)
    if (f.normals[t].z() < -0.3) lower.push_back(t);
  const auto& tri = f.triangles[lower[static_cast<size_t>(r.uniform() * lower.size())]];
  Points piece(3, 6);
  for (int c = 0; c < 3; ++c) {
    const Vec3 v = socket.col(tri[c]);
    piece.col(c) = v;
    piece.col(3 + c) = v * (1 + 5 / rs);
  }
  return {piece, ball};
}

/// Two plates of n vertices one above the other, `gap` apart (a hair: 1e-6…1e-2 mm).
inline PairCase plates_apart(SphereSampler& r, int n, double gap) {
  PairCase c = plates_touching(r, n);
  c.b.row(2).array() += gap;
  return c;
}

/// Two ellipsoid polytopes of n vertices whose boxes overlap while the hulls are
/// apart: the bulk of an assembly's broad-phase candidates.
inline PairCase apart_boxes_overlapping(SphereSampler& r, int n) {
  for (;;) {
    const double ra = 10 + 40 * r.uniform(), rb = 10 + 40 * r.uniform();
    const Vec3 d = (Vec3::Ones() + 0.3 * r.direction()).normalized();
    PairCase c{ellipsoid_polytope(r, n, Vec3::Zero(), ra),
               ellipsoid_polytope(r, n, d * (ra + rb) * (0.8 + 0.4 * r.uniform()), rb)};
    const Vec3 alo = c.a.rowwise().minCoeff(), ahi = c.a.rowwise().maxCoeff();
    const Vec3 blo = c.b.rowwise().minCoeff(), bhi = c.b.rowwise().maxCoeff();
    const bool boxes = (alo.array() <= bhi.array()).all() && (blo.array() <= ahi.array()).all();
    const PairProblem pr(c.a, c.b);
    if (boxes && exact_depth(pr.p(), pr.q()).distance.value_or(0) > 1e-6) return c;
  }
}

/// Deep containment (issue 29), n vertices a part: for even k a shaft of n/2
/// segments (radius 10, 120 long) through the hull of a pulley hub (n/2 segments,
/// radius 30, 20 long), off its axis by up to 5; for odd k a ball of n points
/// (radius 5) deep inside an ellipsoid of n points (radius 50). Placed like the
/// contacts (axes, rotated, float32 far from the origin) by k / 2.
inline PairCase deep_containment(SphereSampler& r, int n, int k) {
  const int seg = std::max(3, n / 2);
  PairCase pc;
  if (k % 2 == 0) {
    const Vec3 off = 5 * r.uniform() * Vec3(r.direction().x(), r.direction().y(), 0);
    Points shaft = ngon_prism(seg, 10, -60, 60, 2 * M_PI * r.uniform());
    shaft.colwise() += off;
    pc = {ngon_prism(seg, 30, -10, 10, 2 * M_PI * r.uniform()), shaft};
  } else {
    pc = {ellipsoid_polytope(r, n, Vec3::Zero(), 50),
          sphere_polytope(r, n, 10 * r.uniform() * r.direction(), 5)};
  }
  return place(r, pc, static_cast<Placement>((k / 2) % 3));
}

/// The contact families, for pdbench's set names.
enum class Contact { kPlates, kSeated, kShaft, kBall, kHairGap };

inline std::string contact_name(Contact c) {
  switch (c) {
    case Contact::kPlates:
      return "plates";
    case Contact::kSeated:
      return "seated";
    case Contact::kShaft:
      return "shaft";
    case Contact::kBall:
      return "ball";
    case Contact::kHairGap:
      return "gap";
  }
  return "?";
}

/// The k-th pair of a contact set of family `c` and size `n` (vertices of the
/// larger part: plate, board, 2·segments of a shaft, ball): fits and gaps cycle
/// with k, and so does the placement (axes, rotated, float32 far from the origin).
inline PairCase contact_case(SphereSampler& r, Contact c, int n, int k) {
  const Placement where = static_cast<Placement>(k % 3);
  PairCase pc;
  switch (c) {
    case Contact::kPlates:
      pc = plates_touching(r, n);
      break;
    case Contact::kSeated:
      pc = seated_component(r, n);
      break;
    case Contact::kShaft:
      pc = shaft_in_bore(r, std::max(3, n / 2), fit_allowance(k / 3));
      break;
    case Contact::kBall:
      pc = ball_in_socket(r, n, fit_allowance(k / 3));
      break;
    case Contact::kHairGap:
      pc = plates_apart(r, n, std::pow(10.0, -6 + (k / 3) % 5));
      break;
  }
  return place(r, pc, where);
}

}  // namespace pd::testgen
