// Tessellation sag (geometry/tessellation_sag.h) against the true deviation of
// generated meshes from the surfaces they tessellate, and the coordinate
// resolution (geometry/coordinate_resolution.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "corpus/cad_shapes.h"
#include "geometry/coordinate_resolution.h"
#include "geometry/tessellation_sag.h"
#include "sag_part.h"

using namespace pd;
using namespace pd::shapes;
using pd_test::chord_sag;

namespace {

const Vec3 kFar(35000.0, -2000.0, 700.0);

/// Signed distance to the true solid (> 0 outside), in the shape's own frame.
using Sdf = std::function<double(const Vec3&)>;

double rho(const Vec3& x) {
  return std::hypot(x.x(), x.y());
}

/// The reference: the mesh's largest excursions outside (concave sag, the
/// mesh larger than the solid) and inside (convex sag) the true surface,
/// sampled on a barycentric grid of every facet (edge midpoints included).
struct Excursion {
  double outside = 0.0, inside = 0.0;
};
Excursion excursion(const Mesh& m, const Sdf& sdf) {
  constexpr int kGrid = 24;
  Excursion e;
  for (long t = 0; t < m.triangles.cols(); ++t) {
    const Vec3 a = m.vertices.col(m.triangles(0, t)), b = m.vertices.col(m.triangles(1, t)),
               c = m.vertices.col(m.triangles(2, t));
    for (int i = 0; i <= kGrid; ++i)
      for (int j = 0; i + j <= kGrid; ++j) {
        const double u = double(i) / kGrid, v = double(j) / kGrid;
        const double d = sdf(a + u * (b - a) + v * (c - a));
        e.outside = std::max(e.outside, d);
        e.inside = std::max(e.inside, -d);
      }
  }
  return e;
}

// A radius whose sag at `segments` is about 0.2 (at least 5): far above the
// float32 step at 35,000 (0.004), so the 10 % is the method's, not rounding's.
double radius_for(int segments) {
  return std::max(5.0, 0.2 / (1 - std::cos(M_PI / segments)));
}

struct Case {
  std::string name;
  Mesh mesh;
  Sdf sdf;
};

std::vector<Case> cases(int n) {
  const double r = radius_for(n);
  std::vector<Case> out;
  // Cylinder: caps are fans from the axis.
  out.push_back(
      {"cylinder", revolution({{0, 0}, {r, 0}, {r, 2 * r}, {0, 2 * r}}, n), [r](const Vec3& x) {
         return std::max({rho(x) - r, -x.z(), x.z() - 2 * r});
       }});
  // Tube: its bore (inner wall) is concave, its outside convex.
  out.push_back(
      {"tube", revolution({{r, 0}, {2 * r, 0}, {2 * r, r}, {r, r}}, n), [r](const Vec3& x) {
         return std::max({rho(x) - 2 * r, r - rho(x), -x.z(), x.z() - r});
       }});
  // UV sphere: n/2 rings of latitude.
  std::vector<Vec2> sphere{{0, -r}};
  for (int j = 1; j < n / 2; ++j) {
    const double phi = -M_PI / 2 + M_PI * j / (n / 2);
    sphere.emplace_back(r * std::cos(phi), r * std::sin(phi));
  }
  sphere.emplace_back(0, r);
  out.push_back({"sphere", revolution(sphere, n), [r](const Vec3& x) { return x.norm() - r; }});
  // Torus: tube radius r/2 about a circle of radius 2r, n segments both ways.
  std::vector<Vec2> torus;
  for (int j = 0; j < n; ++j) {
    const double a = 2 * M_PI * j / n;
    torus.emplace_back(2 * r + 0.5 * r * std::cos(a), 0.5 * r * std::sin(a));
  }
  out.push_back({"torus", revolution(torus, n),
                 [r](const Vec3& x) { return std::hypot(rho(x) - 2 * r, x.z()) - 0.5 * r; }});
  // Cone: base radius r at z = 0, apex at z = 1.5 r.
  out.push_back({"cone", revolution({{0, 0}, {r, 0}, {0, 1.5 * r}}, n), [r](const Vec3& x) {
                   const Vec2 side = Vec2(1.5 * r, r).normalized();  // outward normal of the slant
                   return std::max(-x.z(), (Vec2(rho(x), x.z()) - Vec2(r, 0)).dot(side));
                 }});
  return out;
}

// Within 10 %, or within the coordinates' step where there is no sag (a flat
// cap far from the origin in float32: no measurement resolves below it; and
// the reference's own rounding, 1e-12).
void expect_within_10_percent(double measured, double truth, double resolution,
                              const std::string& what) {
  EXPECT_NEAR(measured, truth, std::max({0.1 * truth, resolution, 1e-12})) << what;
}

}  // namespace

TEST(TessellationSag, BoxHasNoSagAndTwelveDesignEdges) {
  const TessellationSag s = measure_tessellation_sag(translated(box({0, 0, 0}, {10, 20, 30}), kFar),
                                                     CoordinateStorage::kDouble);
  EXPECT_EQ(s.concave, 0.0);
  EXPECT_EQ(s.convex, 0.0);
  EXPECT_TRUE(s.features.empty());
  EXPECT_EQ(s.design_edges, 12);
}

TEST(TessellationSag, CylinderAndBoreMatchTheChordFormula) {
  for (int n : {8, 12, 24, 32, 64, 128, 256}) {
    const double r = radius_for(n);
    // A tube's outside is a convex cylinder of radius 2r, its bore concave, radius r.
    const Mesh tube = revolution({{r, 0}, {2 * r, 0}, {2 * r, r}, {r, r}}, n);
    const TessellationSag s = measure_tessellation_sag(tube, CoordinateStorage::kDouble);
    const std::string what = std::to_string(n) + " segments";
    expect_within_10_percent(s.concave, chord_sag(n, r), s.resolution, what);
    expect_within_10_percent(s.convex, chord_sag(n, 2 * r), s.resolution, what);
    ASSERT_EQ(s.features.size(), 2u) << what;  // the bore and the outside: the flat ends have none
    for (const SagFeature& f : s.features) {
      EXPECT_EQ(f.segments, n) << what;
      const double radius = f.concave > 0 ? r : 2 * r;  // radius of the circle through the vertices
      EXPECT_NEAR(f.radius, radius, 1e-6 * radius) << what;
    }
  }
}

TEST(TessellationSag, WithinTenPercentOfTheTrueDeviation) {
  double worst = 0.0;  // relative error of the convex sags, for the record
  for (int n : {8, 16, 32, 64, 128, 256})
    for (const Case& c : cases(n)) {
      const Excursion truth = excursion(c.mesh, c.sdf);
      for (bool far : {false, true})
        for (bool f32 : {false, true}) {
          Mesh m = far ? translated(c.mesh, kFar) : c.mesh;
          if (f32) m = float32(m);
          const TessellationSag s = measure_tessellation_sag(
              m, f32 ? CoordinateStorage::kFloat32 : CoordinateStorage::kDouble);
          const std::string what = c.name + " " + std::to_string(n) + " segments" +
                                   (far ? " far" : "") + (f32 ? " float32" : "");
          expect_within_10_percent(s.concave, truth.outside, s.resolution, what + " concave");
          expect_within_10_percent(s.convex, truth.inside, s.resolution, what + " convex");
          if (truth.inside > 0)
            worst = std::max(worst, std::abs(s.convex - truth.inside) / truth.inside);
        }
    }
  RecordProperty("worst_relative_error", std::to_string(worst));
  std::printf("worst relative error of convex sags: %.3f\n", worst);
}

TEST(TessellationSag, NearAFeatureTakesItsSagNotThePartsWorst) {
  // A coarse boss (8 segments) and a fine one (128) on one mesh, far apart.
  const Mesh coarse = revolution({{0, 0}, {5, 0}, {5, 10}, {0, 10}}, 8);
  const Mesh fine = translated(revolution({{0, 0}, {5, 0}, {5, 10}, {0, 10}}, 128), {100, 0, 0});
  const TessellationSag s =
      measure_tessellation_sag(joined({coarse, fine}), CoordinateStorage::kDouble);
  ASSERT_EQ(s.features.size(), 2u);
  EXPECT_NEAR(s.convex, chord_sag(8, 5), 1e-9);
  const LocalSag at_fine = sag_near(s, {{98, -1, 4}, {101, 1, 6}});
  EXPECT_NEAR(at_fine.convex, chord_sag(128, 5), 1e-9);
  ASSERT_GE(at_fine.convex_feature, 0);
  EXPECT_EQ(s.features[at_fine.convex_feature].segments, 128);
  const LocalSag nowhere = sag_near(s, {{50, 50, 50}, {51, 51, 51}});
  EXPECT_EQ(nowhere.convex, 0.0);
  EXPECT_EQ(nowhere.convex_feature, -1);
  // Reach grows the query box.
  EXPECT_NEAR(sag_near(s, {{50, 0, 5}, {51, 0, 5}}, 45).convex, chord_sag(8, 5), 1e-9);
}

TEST(TessellationSag, PlacementScalesLengthsAndMovesBoxes) {
  const Mesh boss = revolution({{0, 0}, {5, 0}, {5, 10}, {0, 10}}, 16);
  const TessellationSag s = measure_tessellation_sag(boss, CoordinateStorage::kFloat32);
  Mat4 place = Mat4::Identity();
  place.topLeftCorner<3, 3>() *= 25.4;  // inches to mm
  place(0, 3) = 1000;
  const TessellationSag p = placed_sag(s, place, 25.4);
  EXPECT_NEAR(p.convex, 25.4 * s.convex, 1e-12);
  EXPECT_NEAR(p.resolution, 25.4 * s.resolution, 1e-15);
  ASSERT_EQ(p.features.size(), 1u);
  EXPECT_NEAR(p.features[0].box.lo.x(), 1000 - 25.4 * 5, 1e-9);
  EXPECT_NEAR(p.features[0].radius, 25.4 * 5, 1e-6);
}

TEST(TessellationSag, FlatWallBesideARoundedCornerHasNoSag) {
  // An L-shaped profile whose inner corner is a concave quarter round of
  // radius 5 in 8 segments (32 per turn), extruded: each 67 mm flat wall meets
  // the round at a 5.6° crease (half a segment's turn). The wall is flat; read
  // as spanning that crease with its whole width it would be a 0.82 mm sag.
  // Capped at twice the round's facet width, the worst is the round's own.
  constexpr double a = 80, t = 8, r = 5;
  constexpr int quarter = 8;
  std::vector<Vec2> profile{{0, 0}, {a, 0}, {a, t}};
  for (int k = 0; k <= quarter; ++k) {
    const double phi = -M_PI / 2 - M_PI / 2 * k / quarter;  // from (t + r, t) to (t, t + r)
    profile.emplace_back(t + r + r * std::cos(phi), t + r + r * std::sin(phi));
  }
  profile.insert(profile.end(), {{t, a}, {0, a}});
  const Mesh l = prism(profile, 0, 20);
  for (bool far : {false, true}) {
    const Mesh m = far ? float32(translated(l, kFar)) : l;
    const TessellationSag s =
        measure_tessellation_sag(m, far ? CoordinateStorage::kFloat32 : CoordinateStorage::kDouble);
    const std::string what = far ? "far, float32" : "at the origin";
    expect_within_10_percent(s.concave, chord_sag(4 * quarter, r), s.resolution, what);
    EXPECT_EQ(s.convex, 0.0) << what;
    ASSERT_EQ(s.features.size(), 1u) << what;  // the round and the two walls beside it
    EXPECT_EQ(s.features[0].segments, 4 * quarter) << what;
  }
}
