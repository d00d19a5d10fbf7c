#include "geometry/tessellation_sag.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "tolerances.h"

namespace pd {

namespace {

using Tri = std::array<int, 3>;

// Two creases of one facet within 30° of parallel bend it the same way.
constexpr double kParallelCreases = 0.8660254037844387;  // cos 30°

struct Welded {
  Points v;
  std::vector<Tri> tris;
};

// Vertices at the same coordinates become one (a sort, not a hash: the result
// does not depend on the order of equal keys). Triangles that collapse are dropped.
Welded weld(const Mesh& m) {
  const long n = m.vertices.cols();
  std::vector<long> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0L);
  const auto less = [&](long a, long b) {
    for (int k = 0; k < 3; ++k)
      if (m.vertices(k, a) != m.vertices(k, b)) return m.vertices(k, a) < m.vertices(k, b);
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<int> index(static_cast<size_t>(n));
  Welded w;
  w.v.resize(3, n);
  int count = 0;
  for (long k = 0; k < n; ++k) {
    const long i = order[k];
    if (k == 0 || m.vertices.col(i) != m.vertices.col(order[k - 1]))
      w.v.col(count++) = m.vertices.col(i);
    index[i] = count - 1;
  }
  w.v.conservativeResize(3, count);
  for (long t = 0; t < m.triangles.cols(); ++t) {
    const Tri tri{index[m.triangles(0, t)], index[m.triangles(1, t)], index[m.triangles(2, t)]};
    if (tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2]) w.tris.push_back(tri);
  }
  return w;
}

struct UnionFind {
  std::vector<long> parent;
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0L); }
  long find(long x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(long a, long b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// One manifold edge between triangle t[0] (slot k[0], its vertices u → v) and
// t[1] (slot k[1], v → u), with its exterior angle.
struct Edge {
  std::array<long, 2> t;
  std::array<int, 2> k;
  double angle = 0.0;  ///< exterior dihedral angle, radians in [0, π]
  bool convex = true;
  bool smooth = false;  ///< a tessellation crease (or a flat edge) inside a smooth region
};

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const auto mid = v.begin() + static_cast<long>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// The sag of a quadratic patch over the triangle whose surface normals at the
// corners are n[0..2] (N the facet's unit normal): the height field h over the
// facet's plane vanishes at the corners, and its gradients there are those
// the normals give; h's Hessian H is their least-squares fit along the three
// edges. In barycentric (u, v), h = ½(A u² + 2B uv + C v²) − ½(A u + C v) with
// A = d1ᵀH d1, B = d1ᵀH d2, C = d2ᵀH d2, so its extremes are at the edges'
// midpoints or its stationary point. Returns {max h, max −h}, both ≥ 0 (h
// along the outward normal: > 0 is surface outside the facet, convex), or
// nothing when a corner normal is too far from the facet's.
bool patch_sag(const std::array<Vec3, 3>& p, const std::array<Vec3, 3>& n, const Vec3& N,
               double& convex, double& concave) {
  const Vec3 e1 = (p[1] - p[0]).normalized();
  const Vec3 e2 = N.cross(e1);
  std::array<Eigen::Vector2d, 3> g;
  for (int i = 0; i < 3; ++i) {
    const double c = n[i].dot(N);
    if (!(c >= tol::kSagPatchMinCos)) return false;
    g[i] = Eigen::Vector2d(-n[i].dot(e1), -n[i].dot(e2)) / c;
  }
  const Eigen::Vector2d d1((p[1] - p[0]).dot(e1), 0.0);
  const Eigen::Vector2d d2((p[2] - p[0]).dot(e1), (p[2] - p[0]).dot(e2));
  Eigen::Matrix<double, 6, 3> M;
  Eigen::Matrix<double, 6, 1> r;
  const std::array<std::pair<Eigen::Vector2d, Eigen::Vector2d>, 3> rows{
      {{d1, g[1] - g[0]}, {d2, g[2] - g[0]}, {d2 - d1, g[2] - g[1]}}};
  for (int e = 0; e < 3; ++e) {
    const Eigen::Vector2d& w = rows[e].first;
    M.row(2 * e) << w.x(), w.y(), 0.0;
    M.row(2 * e + 1) << 0.0, w.x(), w.y();
    r(2 * e) = rows[e].second.x();
    r(2 * e + 1) = rows[e].second.y();
  }
  const Eigen::Vector3d abc = M.colPivHouseholderQr().solve(r);
  Eigen::Matrix2d H;
  H << abc(0), abc(1), abc(1), abc(2);
  const double A = d1.dot(H * d1), B = d1.dot(H * d2), C = d2.dot(H * d2);
  double hi = 0.0, lo = 0.0;
  for (double h : {-A / 8, -C / 8, -(A - 2 * B + C) / 8})
    hi = std::max(hi, h), lo = std::min(lo, h);
  const double det = A * C - B * B;
  if (std::abs(det) > 1e-300) {
    const double u = (A * C - B * C) / (2 * det), v = (A * C - A * B) / (2 * det);
    if (u >= 0 && v >= 0 && u + v <= 1) {
      const double h = 0.5 * (A * u * u + 2 * B * u * v + C * v * v) - 0.5 * (A * u + C * v);
      hi = std::max(hi, h), lo = std::min(lo, h);
    }
  }
  convex = hi;
  concave = -lo;
  return std::isfinite(hi) && std::isfinite(lo);
}

}  // namespace

TessellationSag measure_tessellation_sag(const Mesh& m, CoordinateStorage storage) {
  TessellationSag out;
  out.resolution = m.vertices.cols() == 0 ? 0.0
                                          : coordinate_step(max_abs_coordinate(m.vertices),
                                                            storage == CoordinateStorage::kFloat32);
  const Welded w = weld(m);
  const long nt = static_cast<long>(w.tris.size());
  if (nt == 0) return out;
  const auto P = [&](long t, int k) -> Vec3 { return w.v.col(w.tris[t][k % 3]); };

  // Facet normals, areas, corner angles.
  std::vector<Vec3> normal(nt);
  std::vector<double> area(nt);
  std::vector<std::array<double, 3>> corner_angle(nt);
  for (long t = 0; t < nt; ++t) {
    const Vec3 c = (P(t, 1) - P(t, 0)).cross(P(t, 2) - P(t, 0));
    area[t] = 0.5 * c.norm();
    normal[t] = area[t] > 0 ? Vec3(c / (2 * area[t])) : Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = P(t, k + 1) - P(t, k), b = P(t, k + 2) - P(t, k);
      corner_angle[t][k] = std::atan2(a.cross(b).norm(), a.dot(b));
    }
  }

  // Edges: sorted (lower vertex, upper vertex, triangle, slot); a manifold edge
  // is two consistently oriented triangles.
  struct HalfEdge {
    int lo, hi;
    long t;
    int k;
    bool operator<(const HalfEdge& o) const {
      return std::tie(lo, hi, t, k) < std::tie(o.lo, o.hi, o.t, o.k);
    }
  };
  std::vector<HalfEdge> half;
  half.reserve(3 * nt);
  for (long t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int u = w.tris[t][k], v = w.tris[t][(k + 1) % 3];
      half.push_back({std::min(u, v), std::max(u, v), t, k});
    }
  std::sort(half.begin(), half.end());
  std::vector<Edge> edges;
  std::vector<std::array<long, 3>> edge_of(nt, {-1, -1, -1});  // per slot: its manifold edge
  for (size_t s = 0; s < half.size();) {
    size_t e = s;
    while (e < half.size() && half[e].lo == half[s].lo && half[e].hi == half[s].hi) ++e;
    const HalfEdge &h0 = half[s], &h1 = half[s + 1 < e ? s + 1 : s];
    const bool manifold = e - s == 2 && w.tris[h0.t][h0.k] != w.tris[h1.t][h1.k];
    if (manifold && area[h0.t] > 0 && area[h1.t] > 0) {
      Edge edge{{h0.t, h1.t}, {h0.k, h1.k}};
      const Vec3 &n0 = normal[h0.t], &n1 = normal[h1.t];
      edge.angle = std::atan2(n0.cross(n1).norm(), n0.dot(n1));
      // Convex when the second facet's far corner lies below the first's plane.
      edge.convex = n0.dot(P(h1.t, h1.k + 2) - P(h0.t, h0.k)) <= 0;
      edge.smooth = edge.angle <= tol::kSagCreaseAngle;
      edge_of[h0.t][h0.k] = edge_of[h1.t][h1.k] = static_cast<long>(edges.size());
      edges.push_back(edge);
    } else {
      ++out.design_edges;  // boundary, non-manifold, inconsistent or degenerate
    }
    s = e;
  }

  // Smooth regions (facets) and smoothing groups of corners: corners meeting
  // across a smooth edge share one normal.
  UnionFind regions(static_cast<size_t>(nt)), corners(static_cast<size_t>(3 * nt));
  for (const Edge& e : edges) {
    if (!e.smooth) {
      ++out.design_edges;
      continue;
    }
    if (e.angle > 0) ++out.creases;
    regions.join(e.t[0], e.t[1]);
    // t0's slot k0 runs u → v, t1's slot k1 runs v → u.
    corners.join(3 * e.t[0] + e.k[0], 3 * e.t[1] + (e.k[1] + 1) % 3);
    corners.join(3 * e.t[0] + (e.k[0] + 1) % 3, 3 * e.t[1] + e.k[1]);
  }
  std::vector<Vec3> group_normal(3 * nt, Vec3::Zero());
  for (long t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k)
      group_normal[corners.find(3 * t + k)] += corner_angle[t][k] * normal[t];

  // Per facet: the smaller of the crease and patch estimates, by sign.
  std::vector<double> convex(nt, 0.0), concave(nt, 0.0);
  for (long t = 0; t < nt; ++t) {
    if (area[t] <= 0) continue;
    // Creases across different directions (a sphere's latitude and meridian)
    // add up; nearly parallel ones (a cone facet's two sides) bend the same
    // direction, and the larger stands for both.
    struct Crease {
      double sag;
      Vec3 along;
      bool convex;
    };
    std::vector<Crease> creases;
    for (int k = 0; k < 3; ++k) {
      const long e = edge_of[t][k];
      if (e < 0 || !edges[e].smooth || edges[e].angle <= 0) continue;
      const Vec3 along = P(t, k + 1) - P(t, k);
      const double width = 2 * area[t] / along.norm();
      creases.push_back(
          {0.5 * width * std::tan(edges[e].angle / 4), along.normalized(), edges[e].convex});
    }
    std::sort(creases.begin(), creases.end(),
              [](const Crease& a, const Crease& b) { return a.sag > b.sag; });
    double crease_convex = 0.0, crease_concave = 0.0;
    for (size_t i = 0; i < creases.size(); ++i) {
      bool repeats = false;
      for (size_t j = 0; j < i; ++j)
        repeats |= creases[j].convex == creases[i].convex &&
                   std::abs(creases[j].along.dot(creases[i].along)) > kParallelCreases;
      if (!repeats) (creases[i].convex ? crease_convex : crease_concave) += creases[i].sag;
    }
    if (crease_convex == 0 && crease_concave == 0) continue;  // flat around it
    double patch_convex = INFINITY, patch_concave = INFINITY;
    std::array<Vec3, 3> n;
    for (int k = 0; k < 3; ++k) n[k] = group_normal[corners.find(3 * t + k)].normalized();
    if (!patch_sag({P(t, 0), P(t, 1), P(t, 2)}, n, normal[t], patch_convex, patch_concave))
      patch_convex = patch_concave = INFINITY;
    convex[t] = std::min(crease_convex, patch_convex);
    concave[t] = std::min(crease_concave, patch_concave);
  }

  // Features: one per region with a sag.
  std::vector<long> feature_of(nt, -1);
  std::vector<std::vector<double>> angles, radii;
  for (long t = 0; t < nt; ++t) {
    if (convex[t] <= 0 && concave[t] <= 0) continue;
    const long r = regions.find(t);
    if (feature_of[r] < 0) {
      feature_of[r] = static_cast<long>(out.features.size());
      SagFeature f;
      f.box = {P(t, 0), P(t, 0)};
      out.features.push_back(f);
      angles.emplace_back();
      radii.emplace_back();
    }
    SagFeature& f = out.features[feature_of[r]];
    for (int k = 0; k < 3; ++k) f.box = f.box.merged({P(t, k), P(t, k)});
    f.convex = std::max(f.convex, convex[t]);
    f.concave = std::max(f.concave, concave[t]);
    ++f.facets;
  }
  for (const Edge& e : edges) {
    if (!e.smooth || e.angle <= 0) continue;
    const long f = feature_of[regions.find(e.t[0])];
    if (f < 0) continue;
    const double length = (P(e.t[0], e.k[0] + 1) - P(e.t[0], e.k[0])).norm();
    const double width = (area[e.t[0]] + area[e.t[1]]) / length;  // mean of both heights
    angles[f].push_back(e.angle);
    radii[f].push_back(width / (2 * std::sin(e.angle / 2)));
  }
  for (size_t f = 0; f < out.features.size(); ++f) {
    SagFeature& x = out.features[f];
    x.radius = median(radii[f]);
    const double a = median(angles[f]);
    x.segments = a > 0 ? static_cast<int>(std::min(1e6, std::round(2 * M_PI / a))) : 0;
    out.convex = std::max(out.convex, x.convex);
    out.concave = std::max(out.concave, x.concave);
  }
  return out;
}

LocalSag sag_near(const TessellationSag& sag, const Aabb& near, double reach) {
  LocalSag out;
  for (size_t k = 0; k < sag.features.size(); ++k) {
    const SagFeature& f = sag.features[k];
    if (!f.box.inflated(reach).overlaps(near)) continue;
    if (f.concave > out.concave) out.concave = f.concave, out.concave_feature = static_cast<int>(k);
    if (f.convex > out.convex) out.convex = f.convex, out.convex_feature = static_cast<int>(k);
  }
  return out;
}

TessellationSag placed_sag(const TessellationSag& sag, const Mat4& placement, double stretch) {
  TessellationSag out = sag;
  out.concave *= stretch;
  out.convex *= stretch;
  out.resolution *= stretch;
  for (SagFeature& f : out.features) {
    Points corners(3, 8);
    for (int c = 0; c < 8; ++c) {
      const Vec3 x(c & 1 ? f.box.hi.x() : f.box.lo.x(), c & 2 ? f.box.hi.y() : f.box.lo.y(),
                   c & 4 ? f.box.hi.z() : f.box.lo.z());
      corners.col(c) = placement.topLeftCorner<3, 3>() * x + placement.topRightCorner<3, 1>();
    }
    f.box = Aabb::of(corners);
    f.concave *= stretch;
    f.convex *= stretch;
    f.radius *= stretch;
  }
  return out;
}

}  // namespace pd
