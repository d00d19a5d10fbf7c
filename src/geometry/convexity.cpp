#include "geometry/convexity.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <utility>

#include "geometry/hull.h"
#include "geometry/mesh_intersect.h"
#include "geometry/surface_polygons.h"
#include "geometry/triangle_tree.h"
#include "tolerances.h"

namespace pd {

namespace {

// Fills h's facets from h.centred (or takes `known`); false when it is flat
// or smaller.
bool facets_of(HullOfPoints& h, const HullTriangles* known = nullptr) {
  const Points& p = h.centred;
  if (known) {
    if (known->triangles.empty()) return false;
    static_cast<HullTriangles&>(h.f) = *known;
    for (size_t i = 0; i < h.f.triangles.size(); ++i) {  // through the farthest corner
      double at = -INFINITY;
      for (int k : h.f.triangles[i]) at = std::max(at, h.f.normals[i].dot(p.col(k)));
      h.f.offsets.push_back(-at);
    }
  } else if (p.cols() < 4 || !hull_facets(p, h.f)) {
    return false;
  }
  h.facets = true;
  for (std::size_t i = 0; i < h.f.triangles.size(); ++i) {
    const auto& t = h.f.triangles[i];
    const double a = 0.5 * (p.col(t[1]) - p.col(t[0])).cross(p.col(t[2]) - p.col(t[0])).norm();
    h.area.push_back(a);
    h.total_area += a;
    h.volume += a * -h.f.offsets[i] / 3.0;  // pyramids from the origin (signed)
  }
  return h.solid();
}

}  // namespace

HullOfPoints hull_of_points(const Points& points) {
  HullOfPoints h;
  h.centre = points.rowwise().mean();
  h.centred = points.colwise() - h.centre;
  facets_of(h);
  return h;
}

HullOfPoints hull_of_points(const Points& points, const HullTriangles& facets) {
  HullOfPoints h;
  h.centre = points.rowwise().mean();
  h.centred = points.colwise() - h.centre;
  facets_of(h, &facets);
  return h;
}

Concavity hull_concavity(const Points& points, const PreparedMesh& part, double void_radius,
                         double missing_volume, const Points& surface, int samples,
                         double stop_above, const SurfacePolygons* on_part) {
  return hull_concavity(hull_of_points(points), part, void_radius, missing_volume, surface, samples,
                        stop_above, on_part);
}

Concavity hull_concavity(const HullOfPoints& h, const PreparedMesh& part, double void_radius,
                         double missing_volume, const Points& surface, int samples,
                         double stop_above, const SurfacePolygons* on_part) {
  Concavity c;
  // qhull works on centred coordinates; distances are taken back in the part's.
  const Vec3& centre = h.centre;
  const Points& p = h.centred;
  if (!h.solid()) return c;
  PreparedMesh::Hint near;  // successive samples are neighbours
  auto consider = [&](const Vec3& x) {
    // On the part's surface (within its `within`): cannot raise the estimate
    // above that, so the query is saved.
    if (on_part && on_part->covers(x + centre)) return;
    // The previous query's nearest point is on the surface: no farther than
    // it, x cannot raise the estimate (a sample must exceed it strictly).
    if (near.face >= 0 && (x + centre - near.point).norm() <= c.value) return;
    const double d = part.outside_distance(x + centre, near);
    if (d > c.value) c.value = d, c.witness = x + centre;
    c.stopped = c.value > stop_above;
  };
  auto finish = [&] {
    if (c.value > 0) c.closest = part.closest_point(c.witness);
    return c;
  };

  // A lattice on every facet: k subdivisions of its longest edge, spacing s
  // chosen so that the lattices hold about `samples` points in all.
  double sum_l2 = 0.0;
  std::vector<double> longest(h.f.triangles.size());
  for (std::size_t i = 0; i < h.f.triangles.size(); ++i) {
    const auto& t = h.f.triangles[i];
    longest[i] = std::max({(p.col(t[1]) - p.col(t[0])).norm(), (p.col(t[2]) - p.col(t[1])).norm(),
                           (p.col(t[0]) - p.col(t[2])).norm()});
    sum_l2 += longest[i] * longest[i];
  }
  const double s = std::sqrt(sum_l2 / (2.0 * std::max(samples, 1)));
  // A hull vertex is a corner of every facet around it (six on a ball's hull,
  // where every facet is a single cell): measured once, the others cannot
  // raise the estimate past its own first measure.
  std::vector<char> corner_seen(static_cast<std::size_t>(p.cols()), 0);
  for (std::size_t i = 0; i < h.f.triangles.size(); ++i) {
    const auto& t = h.f.triangles[i];
    const int k = std::max(1, static_cast<int>(std::ceil(longest[i] / s)));
    const Vec3 a = p.col(t[0]), ab = p.col(t[1]) - a, ac = p.col(t[2]) - a;
    for (int u = 0; u <= k; ++u)
      for (int v = 0; u + v <= k; ++v) {
        const int corner = u == 0 && v == 0 ? t[0] : u == k ? t[1] : v == k ? t[2] : -1;
        if (corner >= 0 && std::exchange(corner_seen[corner], char{1})) continue;
        consider(corner >= 0 ? Vec3(p.col(corner))
                             : a + (double(u) / k) * ab + (double(v) / k) * ac);
        if (c.stopped) return finish();
      }
    // Any point of a lattice cell is within its longest edge / √3 of a corner.
    c.resolution = std::max(c.resolution, longest[i] / k / std::sqrt(3.0));
  }

  // Surface points projected onto their nearest facet (from inside the hull).
  // A surface point that is a hull vertex projects onto itself, which the
  // lattices measured as a facet's corner (on a convex part, every one).
  std::vector<std::array<double, 3>> hull_vertices;
  for (std::size_t i = 0; i < corner_seen.size(); ++i)
    if (corner_seen[i]) hull_vertices.push_back({p(0, long(i)), p(1, long(i)), p(2, long(i))});
  std::sort(hull_vertices.begin(), hull_vertices.end());
  // The nearest point of the hull's boundary to a point inside it is its
  // projection onto the nearest facet plane, which lies in that facet: the
  // nearest point of the facets' triangles, found in a tree (a scan of every
  // facet per point cost O(points × facets): most of a fine part's screen).
  const Vec3 lo = p.rowwise().minCoeff(), hi = p.rowwise().maxCoeff();
  std::optional<TriangleTree> facets;
  int hint = -1;
  for (long i = 0; i < surface.cols(); ++i) {
    const Vec3 y = surface.col(i) - centre;
    if ((y.array() < lo.array()).any() || (y.array() > hi.array()).any()) continue;
    if (std::binary_search(hull_vertices.begin(), hull_vertices.end(),
                           std::array<double, 3>{y.x(), y.y(), y.z()}))
      continue;
    if (!facets) {
      std::vector<std::array<Vec3, 3>> corners;
      corners.reserve(h.f.triangles.size());
      for (const auto& t : h.f.triangles)
        corners.push_back({p.col(t[0]), p.col(t[1]), p.col(t[2])});
      facets.emplace(corners);
    }
    const TriangleTree::Nearest x = facets->nearest(y, hint);
    hint = x.face;
    // A point off the hull by more than rounding is not the part's (another
    // shell's hull holds it): skipped, as its nearest facet says.
    const double on = tol::kOnHull * (hi - lo).norm();
    if (h.f.normals[size_t(x.face)].dot(y) + h.f.offsets[size_t(x.face)] > on) continue;
    consider(x.point);
    if (c.stopped) return finish();
  }

  // Enclosed voids: only a void holding a ball of radius void_radius matters,
  // and that needs at least the ball's volume missing.
  const double ball = 4.0 / 3.0 * M_PI * std::pow(void_radius, 3);
  if (missing_volume < 0 || missing_volume > ball) {
    const double g = std::cbrt((hi - lo).prod() / std::max(samples, 1));
    if (g > 0) {
      // A point inside the part is the centre of a ball of the part (its
      // distance to the surface): later grid points in such a ball are inside
      // too, and cannot raise the estimate. The last few balls are kept: the
      // grid's next line passes through the balls of the line before.
      constexpr size_t kBalls = 64;
      std::array<std::pair<Vec3, double>, kBalls> balls;  // centre, squared radius
      size_t kept = 0;
      const auto in_a_ball = [&](const Vec3& q) {
        for (size_t i = 0; i < std::min(kept, kBalls); ++i)
          if ((q - balls[i].first).squaredNorm() < balls[i].second) return true;
        return false;
      };
      for (double x = lo.x() + g / 2; x < hi.x(); x += g)
        for (double y = lo.y() + g / 2; y < hi.y(); y += g)
          for (double z = lo.z() + g / 2; z < hi.z(); z += g) {
            const Vec3 q(x, y, z);
            if (in_a_ball(q)) continue;
            bool in = true;
            for (std::size_t i = 0; i < h.f.normals.size() && in; ++i)
              in = h.f.normals[i].dot(q) + h.f.offsets[i] <= 0;
            if (!in) continue;
            const double sd = part.signed_distance(q + centre);  // > 0 inside
            if (sd > 0) {
              balls[kept++ % kBalls] = {q, sd * sd};
              continue;
            }
            if (-sd > c.value && !(on_part && on_part->covers(q + centre))) {
              c.value = -sd, c.witness = q + centre;
              c.stopped = c.value > stop_above;
              if (c.stopped) return finish();
            }
          }
      c.resolution = std::max(c.resolution, g * std::sqrt(3.0) / 2);
    }
  }
  return finish();
}

double mesh_volume(const Mesh& m) {
  if (m.vertices.cols() == 0) return 0.0;
  const Vec3 centre = m.vertices.rowwise().mean();
  double v = 0.0;
  for (long t = 0; t < m.triangles.cols(); ++t) {
    const Vec3 a = m.vertices.col(m.triangles(0, t)) - centre,
               b = m.vertices.col(m.triangles(1, t)) - centre,
               c = m.vertices.col(m.triangles(2, t)) - centre;
    v += a.dot(b.cross(c));
  }
  return std::abs(v) / 6.0;
}

std::vector<std::vector<int>> shell_triangles(const Mesh& m) {
  const long n = m.vertices.cols();
  // Vertices with equal coordinates are one (STL repeats each corner).
  const std::vector<int> first = first_at_same_position(m.vertices);
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (int v = 0; v < n; ++v)
    if (first[v] != v) parent[root(v)] = root(first[v]);
  for (long t = 0; t < m.triangles.cols(); ++t) {
    parent[root(m.triangles(1, t))] = root(m.triangles(0, t));
    parent[root(m.triangles(2, t))] = root(m.triangles(0, t));
  }
  std::map<int, int> shell_of_root;
  std::vector<std::vector<int>> tris;
  for (long t = 0; t < m.triangles.cols(); ++t) {
    const int r = root(m.triangles(0, t));
    auto [it, fresh] = shell_of_root.emplace(r, static_cast<int>(tris.size()));
    if (fresh) tris.emplace_back();
    tris[it->second].push_back(static_cast<int>(t));
  }
  return tris;
}

std::vector<Mesh> mesh_shells(const Mesh& m) {
  const std::vector<std::vector<int>> tris = shell_triangles(m);
  std::vector<Mesh> shells;
  for (const auto& ts : tris) {
    std::map<int, int> local;
    Mesh s;
    s.triangles.resize(3, static_cast<long>(ts.size()));
    std::vector<int> cols;
    for (std::size_t i = 0; i < ts.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        const int v = m.triangles(k, ts[i]);
        auto [it, fresh] = local.emplace(v, static_cast<int>(cols.size()));
        if (fresh) cols.push_back(v);
        s.triangles(k, static_cast<long>(i)) = it->second;
      }
    s.vertices.resize(3, static_cast<long>(cols.size()));
    for (std::size_t i = 0; i < cols.size(); ++i) s.vertices.col(i) = m.vertices.col(cols[i]);
    shells.push_back(std::move(s));
  }
  return shells;
}

namespace {

// Shell i lies inside shell j (even-odd rule of shell j alone).
bool nested(const std::vector<Mesh>& shells) {
  std::vector<Vec3> lo, hi;
  for (const Mesh& s : shells)
    lo.push_back(s.vertices.rowwise().minCoeff()), hi.push_back(s.vertices.rowwise().maxCoeff());
  for (std::size_t j = 0; j < shells.size(); ++j) {
    std::unique_ptr<PreparedMesh> pj;
    for (std::size_t i = 0; i < shells.size(); ++i) {
      if (i == j || (lo[i].array() < lo[j].array()).any() || (hi[i].array() > hi[j].array()).any())
        continue;
      if (!pj) pj = std::make_unique<PreparedMesh>(shells[j]);
      if (pj->inside(shells[i].vertices.col(0))) return true;
    }
  }
  return false;
}

}  // namespace

double coordinate_noise(const Points& v) {
  if (v.cols() == 0) return 0.0;
  const double size = (v.rowwise().maxCoeff() - v.rowwise().minCoeff()).norm();
  return std::max(tol::kNoiseFloor * size,
                  tol::kNoiseUlps * std::ldexp(v.cwiseAbs().maxCoeff(), -24));
}

SurfacePolygons triangle_polygons(const Mesh& m, double within) {
  Points corners(3, 3 * m.triangles.cols());
  std::vector<std::pair<long, long>> ranges;
  for (long t = 0; t < m.triangles.cols(); ++t) {
    for (int k = 0; k < 3; ++k) corners.col(3 * t + k) = m.vertices.col(m.triangles(k, t));
    ranges.push_back({3 * t, 3 * t + 3});
  }
  return SurfacePolygons(std::move(corners), ranges, within);
}

ConvexityScreen screen_convexity(const Mesh& m, double concavity_tol, double stop_above,
                                 const Points* hull_points, const HullTriangles* hull_facets) {
  return screen_convexity(m, PreparedMesh(m), concavity_tol, stop_above, hull_points, hull_facets);
}

ConvexityScreen screen_convexity(const Mesh& m, const PreparedMesh& part, double concavity_tol,
                                 double stop_above, const Points* hull_points,
                                 const HullTriangles* hull_facets) {
  ConvexityScreen r;
  r.closed = part.closed();
  // Each position once (an STL file repeats every corner): hulled when no
  // hull points are given, and the surface points the estimate projects.
  std::optional<Points> distinct;
  const auto distinct_of_m = [&]() -> const Points& {
    if (!distinct) distinct = distinct_positions(m.vertices, first_at_same_position(m.vertices));
    return *distinct;
  };
  const Points& points = hull_points ? *hull_points : distinct_of_m();
  const HullOfPoints h = hull_points && hull_facets ? hull_of_points(points, *hull_facets)
                                                    : hull_of_points(points);  // the estimate's too
  const double hull_volume = h.solid() ? h.volume : 0.0;
  const double missing = r.closed ? hull_volume - mesh_volume(m) : -1.0;
  // A coarse screen first, without the part's polygons (building them costs
  // more than a nonconvex part's whole estimate): any sample's distance is a
  // lower bound, and a gear's or a housing's first hull facets decide.
  r.concavity = hull_concavity(h, part, concavity_tol, missing, Points(3, 0),
                               tol::kDecomposeScreenSamples, stop_above);
  if (r.concavity.stopped) return r;
  // Samples on the mesh's own faces are on it: only the rest are measured
  // (a convex mesh's hull facets are its faces). Samples within a quarter of
  // the tolerance of them count as on them: the estimate only decides whether
  // the part is convex within the tolerance (parts.cpp), and those cannot
  // take it there (a float32 shaft's caps lie a few float steps off its hull's).
  const SurfacePolygons faces = triangle_polygons(m, 0.25 * concavity_tol);
  r.concavity = hull_concavity(h, part, concavity_tol, missing, distinct_of_m(), kConvexitySamples,
                               stop_above, &faces);
  return r;
}

Convexity measure_convexity(const Mesh& m, double concavity_tol, double stop_above) {
  Convexity r;
  const PreparedMesh part(m);
  r.closed = part.closed();
  r.shells = part.shells();
  const HullOfPoints h = hull_of_points(m.vertices);  // the estimate's too
  if (h.solid()) {
    r.hull_volume = h.volume;
    r.hull_area = h.total_area;
  }
  if (r.closed) {
    r.volume = mesh_volume(m);
    if (r.hull_area > 0) r.screen = std::max(0.0, r.hull_volume - r.volume) / r.hull_area;
  }
  r.concavity = hull_concavity(h, part, concavity_tol, r.closed ? r.hull_volume - r.volume : -1.0,
                               distinct_positions(m.vertices, first_at_same_position(m.vertices)),
                               kConvexitySamples, stop_above);
  r.convex = r.concavity.value <= concavity_tol;
  if (!r.convex && r.shells > 1) {
    const std::vector<Mesh> shells = mesh_shells(m);
    r.nested_shells = nested(shells);
    r.shells_convex =
        !r.nested_shells && std::all_of(shells.begin(), shells.end(), [&](const Mesh& s) {
          const PreparedMesh ps(s);
          const HullOfPoints hs = hull_of_points(s.vertices);
          const double hv = hs.solid() ? hs.volume : 0.0;
          // Only the comparison is kept: the estimate may stop at the tolerance.
          return hull_concavity(hs, ps, concavity_tol, ps.closed() ? hv - mesh_volume(s) : -1.0,
                                distinct_positions(s.vertices, first_at_same_position(s.vertices)),
                                kConvexitySamples, concavity_tol)
                     .value <= concavity_tol;
        });
  }
  return r;
}

}  // namespace pd
