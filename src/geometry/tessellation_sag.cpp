#include "geometry/tessellation_sag.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <tuple>
#include <utility>

#include "geometry/union_find.h"
#include "tolerances.h"

namespace pd {

namespace {

using Tri = std::array<int, 3>;

// Two creases of one facet within 30° of parallel bend it the same way.
constexpr double kParallelCreases = 0.8660254037844387;  // cos 30°

struct Welded {
  Points v;
  std::vector<Tri> tris;
  /// Corner k (taken mod 3, so k + 1 and k + 2 name the next ones) of triangle t.
  Vec3 corner(long t, int k) const { return v.col(tris[t][k % 3]); }
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

// The facets' geometry, computed once: every later pass reads it.
struct Facets {
  std::vector<Vec3> normal;  ///< unit; zero for a degenerate (zero-area) facet
  std::vector<double> area;
  std::vector<std::array<double, 3>>
      corner_angle;  ///< weights of the facet in its corners' normals
};

Facets facet_geometry(const Welded& w) {
  const long nt = static_cast<long>(w.tris.size());
  Facets f;
  f.normal.resize(nt);
  f.area.resize(nt);
  f.corner_angle.resize(nt);
  for (long t = 0; t < nt; ++t) {
    const Vec3 c = (w.corner(t, 1) - w.corner(t, 0)).cross(w.corner(t, 2) - w.corner(t, 0));
    f.area[t] = 0.5 * c.norm();
    f.normal[t] = f.area[t] > 0 ? Vec3(c / (2 * f.area[t])) : Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = w.corner(t, k + 1) - w.corner(t, k), b = w.corner(t, k + 2) - w.corner(t, k);
      f.corner_angle[t][k] = std::atan2(a.cross(b).norm(), a.dot(b));
    }
  }
  return f;
}

// One side of an edge, keyed by its vertices lower first so that both sides
// of an edge sort next to each other (then by triangle: a stable order).
struct HalfEdge {
  int lo, hi;
  long t;
  int k;
  bool operator<(const HalfEdge& o) const {
    return std::tie(lo, hi, t, k) < std::tie(o.lo, o.hi, o.t, o.k);
  }
};

std::vector<HalfEdge> sorted_half_edges(const Welded& w) {
  const long nt = static_cast<long>(w.tris.size());
  std::vector<HalfEdge> half;
  half.reserve(3 * nt);
  for (long t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int u = w.tris[t][k], v = w.tris[t][(k + 1) % 3];
      half.push_back({std::min(u, v), std::max(u, v), t, k});
    }
  std::sort(half.begin(), half.end());
  return half;
}

struct EdgeTable {
  std::vector<Edge> edges;
  std::vector<std::array<long, 3>> edge_of;  ///< per facet slot: its manifold edge, or -1
};

// The manifold edges (two consistently oriented, non-degenerate facets) with
// their angles; every other edge (boundary, non-manifold, inconsistent or
// degenerate) is counted in `design_edges`, as it bounds a smooth region too.
EdgeTable manifold_edges(const Welded& w, const Facets& f, long& design_edges) {
  const std::vector<HalfEdge> half = sorted_half_edges(w);
  EdgeTable out;
  out.edge_of.assign(w.tris.size(), {-1, -1, -1});
  for (size_t s = 0; s < half.size();) {
    size_t e = s;
    while (e < half.size() && half[e].lo == half[s].lo && half[e].hi == half[s].hi) ++e;
    const HalfEdge &h0 = half[s], &h1 = half[s + 1 < e ? s + 1 : s];
    const bool manifold = e - s == 2 && w.tris[h0.t][h0.k] != w.tris[h1.t][h1.k];
    if (manifold && f.area[h0.t] > 0 && f.area[h1.t] > 0) {
      Edge edge{{h0.t, h1.t}, {h0.k, h1.k}};
      const Vec3 &n0 = f.normal[h0.t], &n1 = f.normal[h1.t];
      edge.angle = std::atan2(n0.cross(n1).norm(), n0.dot(n1));
      // Convex when the second facet's far corner lies below the first's plane.
      edge.convex = n0.dot(w.corner(h1.t, h1.k + 2) - w.corner(h0.t, h0.k)) <= 0;
      edge.smooth = edge.angle <= tol::kSagCreaseAngle;
      out.edge_of[h0.t][h0.k] = out.edge_of[h1.t][h1.k] = static_cast<long>(out.edges.size());
      out.edges.push_back(edge);
    } else {
      ++design_edges;
    }
    s = e;
  }
  return out;
}

// Smooth regions (facets) and smoothing groups of corners: corners meeting
// across a smooth edge share one normal, as the CAD surface has one there.
struct Smoothing {
  UnionFind regions;               ///< facets joined across smooth edges
  UnionFind corners;               ///< corner 3t + k joined across smooth edges
  std::vector<Vec3> group_normal;  ///< per corner group (at its root): angle-weighted sum
};

// Also counts the creases and the sharp (design) edges into `out`.
Smoothing smooth_groups(const Facets& f, const std::vector<Edge>& edges, TessellationSag& out) {
  const long nt = static_cast<long>(f.area.size());
  Smoothing s{UnionFind(static_cast<size_t>(nt)), UnionFind(static_cast<size_t>(3 * nt)), {}};
  for (const Edge& e : edges) {
    if (!e.smooth) {
      ++out.design_edges;
      continue;
    }
    if (e.angle > 0) ++out.creases;
    s.regions.join(e.t[0], e.t[1]);
    // t0's slot k0 runs u → v, t1's slot k1 runs v → u.
    s.corners.join(3 * e.t[0] + e.k[0], 3 * e.t[1] + (e.k[1] + 1) % 3);
    s.corners.join(3 * e.t[0] + (e.k[0] + 1) % 3, 3 * e.t[1] + e.k[1]);
  }
  s.group_normal.assign(3 * nt, Vec3::Zero());
  for (long t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k)
      s.group_normal[s.corners.find(3 * t + k)] += f.corner_angle[t][k] * f.normal[t];
  return s;
}

// Facet t's sag from the creases of its smooth edges, {convex, concave}.
// Creases across different directions (a sphere's latitude and meridian) add
// up; nearly parallel ones (a cone facet's two sides) bend the same
// direction, and the larger stands for both.
std::pair<double, double> crease_sag(const Welded& w, const Facets& f, const EdgeTable& table,
                                     long t) {
  struct Crease {
    double sag;
    Vec3 along;
    bool convex;
  };
  std::vector<Crease> creases;
  for (int k = 0; k < 3; ++k) {
    const long e = table.edge_of[t][k];
    if (e < 0) continue;  // a design edge: not a crease
    const Edge& edge = table.edges[e];
    if (!edge.smooth || edge.angle <= 0) continue;
    const Vec3 along = w.corner(t, k + 1) - w.corner(t, k);
    // The facet's width across the crease, at most kSagChordRatio times its
    // neighbour's there: a flat wall beside a round's first facet turns only
    // by the round's half segment, and is not a chord of that round.
    const long other = edge.t[0] == t ? edge.t[1] : edge.t[0];
    const double width =
        2 * std::min(f.area[t], tol::kSagChordRatio * f.area[other]) / along.norm();
    creases.push_back({0.5 * width * std::tan(edge.angle / 4), along.normalized(), edge.convex});
  }
  std::sort(creases.begin(), creases.end(),
            [](const Crease& a, const Crease& b) { return a.sag > b.sag; });
  double convex = 0.0, concave = 0.0;
  for (size_t i = 0; i < creases.size(); ++i) {
    bool repeats = false;
    for (size_t j = 0; j < i; ++j)
      repeats |= creases[j].convex == creases[i].convex &&
                 std::abs(creases[j].along.dot(creases[i].along)) > kParallelCreases;
    if (!repeats) (creases[i].convex ? convex : concave) += creases[i].sag;
  }
  return {convex, concave};
}

struct FacetSags {
  std::vector<double> convex, concave;
};

// Per facet: the smaller of the crease and patch estimates, by sign (see the
// header: each is exact where the other is not). Facets flat around are 0.
FacetSags facet_sags(const Welded& w, const Facets& f, const EdgeTable& table, Smoothing& s) {
  const long nt = static_cast<long>(w.tris.size());
  FacetSags out{std::vector<double>(nt, 0.0), std::vector<double>(nt, 0.0)};
  for (long t = 0; t < nt; ++t) {
    if (f.area[t] <= 0) continue;
    const auto [crease_convex, crease_concave] = crease_sag(w, f, table, t);
    if (crease_convex == 0 && crease_concave == 0) continue;  // flat around it
    double patch_convex = INFINITY, patch_concave = INFINITY;
    std::array<Vec3, 3> n;
    for (int k = 0; k < 3; ++k) n[k] = s.group_normal[s.corners.find(3 * t + k)].normalized();
    if (!patch_sag({w.corner(t, 0), w.corner(t, 1), w.corner(t, 2)}, n, f.normal[t], patch_convex,
                   patch_concave))
      patch_convex = patch_concave = INFINITY;
    out.convex[t] = std::min(crease_convex, patch_convex);
    out.concave[t] = std::min(crease_concave, patch_concave);
  }
  return out;
}

// One feature per smooth region with a sag, in the order of its first facet
// (so the list does not depend on the union-find's roots); returns each
// region root's feature, -1 for none.
std::vector<long> gather_features(const Welded& w, const FacetSags& sag, UnionFind& regions,
                                  std::vector<SagFeature>& features) {
  const long nt = static_cast<long>(w.tris.size());
  std::vector<long> feature_of(nt, -1);
  for (long t = 0; t < nt; ++t) {
    if (sag.convex[t] <= 0 && sag.concave[t] <= 0) continue;
    const long r = regions.find(t);
    if (feature_of[r] < 0) {
      feature_of[r] = static_cast<long>(features.size());
      SagFeature f;
      f.box = {w.corner(t, 0), w.corner(t, 0)};
      features.push_back(f);
    }
    SagFeature& f = features[feature_of[r]];
    for (int k = 0; k < 3; ++k) f.box = f.box.merged({w.corner(t, k), w.corner(t, k)});
    f.convex = std::max(f.convex, sag.convex[t]);
    f.concave = std::max(f.concave, sag.concave[t]);
    ++f.facets;
  }
  return feature_of;
}

// Each feature's patches: its facets bucketed by the grid cell of their
// centroid (kSagPatchCells cells along the feature box's longest side), in the
// order of the cells (a sort: the result does not depend on the facets' order).
void gather_patches(const Welded& w, const FacetSags& sag, UnionFind& regions,
                    const std::vector<long>& feature_of, std::vector<SagFeature>& features) {
  struct Member {
    long feature;
    std::array<long, 3> cell;
    long t;
    bool operator<(const Member& o) const {
      return std::tie(feature, cell, t) < std::tie(o.feature, o.cell, o.t);
    }
  };
  std::vector<Member> members;
  const long nt = static_cast<long>(w.tris.size());
  for (long t = 0; t < nt; ++t) {
    if (sag.convex[t] <= 0 && sag.concave[t] <= 0) continue;
    const long k = feature_of[regions.find(t)];
    const Aabb& box = features[k].box;
    const double size = (box.hi - box.lo).maxCoeff() / tol::kSagPatchCells;
    const Vec3 c = (w.corner(t, 0) + w.corner(t, 1) + w.corner(t, 2)) / 3;
    std::array<long, 3> cell{0, 0, 0};
    for (int d = 0; d < 3; ++d)
      if (size > 0)
        cell[d] = std::clamp(static_cast<long>(std::floor((c(d) - box.lo(d)) / size)), 0L,
                             static_cast<long>(tol::kSagPatchCells) - 1);
    members.push_back({k, cell, t});
  }
  std::sort(members.begin(), members.end());
  for (size_t i = 0; i < members.size(); ++i) {
    const Member& m = members[i];
    std::vector<SagPatch>& patches = features[m.feature].patches;
    if (i == 0 || members[i - 1].feature != m.feature || members[i - 1].cell != m.cell)
      patches.push_back({{w.corner(m.t, 0), w.corner(m.t, 0)}});
    SagPatch& p = patches.back();
    for (int k = 0; k < 3; ++k) p.box = p.box.merged({w.corner(m.t, k), w.corner(m.t, k)});
    p.convex = std::max(p.convex, sag.convex[m.t]);
    p.concave = std::max(p.concave, sag.concave[m.t]);
  }
}

// Each feature's radius and segments per turn, from the medians over its
// creases (a median: a few odd creases at a region's seam do not move it).
void describe_features(const Welded& w, const Facets& f, const std::vector<Edge>& edges,
                       UnionFind& regions, const std::vector<long>& feature_of,
                       std::vector<SagFeature>& features) {
  std::vector<std::vector<double>> angles(features.size()), radii(features.size());
  for (const Edge& e : edges) {
    if (!e.smooth || e.angle <= 0) continue;
    const long k = feature_of[regions.find(e.t[0])];
    if (k < 0) continue;
    const double length = (w.corner(e.t[0], e.k[0] + 1) - w.corner(e.t[0], e.k[0])).norm();
    const double width = (f.area[e.t[0]] + f.area[e.t[1]]) / length;  // mean of both heights
    angles[k].push_back(e.angle);
    radii[k].push_back(width / (2 * std::sin(e.angle / 2)));
  }
  for (size_t k = 0; k < features.size(); ++k) {
    SagFeature& x = features[k];
    x.radius = median(radii[k]);
    const double a = median(angles[k]);
    x.segments = a > 0 ? static_cast<int>(std::min(1e6, std::round(2 * M_PI / a))) : 0;
  }
}

}  // namespace

TessellationSag measure_tessellation_sag(const Mesh& m, CoordinateStorage storage) {
  TessellationSag out;
  out.resolution = m.vertices.cols() == 0 ? 0.0
                                          : coordinate_step(max_abs_coordinate(m.vertices),
                                                            storage == CoordinateStorage::kFloat32);
  const Welded w = weld(m);
  if (w.tris.empty()) return out;
  const Facets facets = facet_geometry(w);
  const EdgeTable table = manifold_edges(w, facets, out.design_edges);
  Smoothing smoothing = smooth_groups(facets, table.edges, out);
  const FacetSags sag = facet_sags(w, facets, table, smoothing);
  const std::vector<long> feature_of = gather_features(w, sag, smoothing.regions, out.features);
  describe_features(w, facets, table.edges, smoothing.regions, feature_of, out.features);
  gather_patches(w, sag, smoothing.regions, feature_of, out.features);
  for (const SagFeature& x : out.features) {
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

LocalSag sag_at(const TessellationSag& sag, const Vec3& at, double reach) {
  const Aabb point{at, at};
  LocalSag out;
  for (size_t k = 0; k < sag.features.size(); ++k) {
    const SagFeature& f = sag.features[k];
    if (!f.box.inflated(reach).overlaps(point)) continue;
    for (const SagPatch& p : f.patches) {
      if (!p.box.inflated(reach).overlaps(point)) continue;
      if (p.concave > out.concave)
        out.concave = p.concave, out.concave_feature = static_cast<int>(k);
      if (p.convex > out.convex) out.convex = p.convex, out.convex_feature = static_cast<int>(k);
    }
  }
  return out;
}

namespace {

// The box of a box's eight corners mapped by `placement` (on the stack: a
// part's every patch box is placed, in every run).
Aabb placed_box(const Aabb& box, const Mat4& placement) {
  Eigen::Matrix<double, 3, 8> corners;
  for (int c = 0; c < 8; ++c) {
    const Vec3 x(c & 1 ? box.hi.x() : box.lo.x(), c & 2 ? box.hi.y() : box.lo.y(),
                 c & 4 ? box.hi.z() : box.lo.z());
    corners.col(c) = placement.topLeftCorner<3, 3>() * x + placement.topRightCorner<3, 1>();
  }
  return {corners.rowwise().minCoeff(), corners.rowwise().maxCoeff()};
}

}  // namespace

TessellationSag placed_sag(const TessellationSag& sag, const Mat4& placement, double stretch) {
  if (stretch == 1.0 && placement == Mat4::Identity()) return sag;  // parts placed as their files
  TessellationSag out = sag;
  out.concave *= stretch;
  out.convex *= stretch;
  out.resolution *= stretch;
  for (SagFeature& f : out.features) {
    f.box = placed_box(f.box, placement);
    for (SagPatch& p : f.patches) {
      p.box = placed_box(p.box, placement);
      p.concave *= stretch;
      p.convex *= stretch;
    }
    f.concave *= stretch;
    f.convex *= stretch;
    f.radius *= stretch;
  }
  return out;
}

}  // namespace pd
