#include "geometry/decompose.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <deque>
#include <map>
#include <memory>
#include <queue>
#include <set>

#include "geometry/convexity.h"
#include "geometry/hull.h"
#include "geometry/mesh_intersect.h"
#include "geometry/surface_polygons.h"
#include "tolerances.h"

namespace pd {

namespace {

using Clock = std::chrono::steady_clock;

struct Plane {
  Vec3 n;  // the cell is n·x <= d
  double d;
};

// A convex cell of space (planes) and the triangles of the mesh that reach it.
struct Cell {
  std::vector<Plane> planes;
  std::vector<int> tris;
  int depth = 0;
};

// The part inside a cell (or a union of cells after a merge), as the vertex set
// of its hull.
struct Piece {
  Points points;                             // hull vertices, centred coordinates
  Points surface;                            // every clipped point (the part's surface in the cell)
  std::vector<int> tris;                     // triangles reaching the cell
  std::vector<std::pair<long, long>> polys;  // clipped faces: column ranges of surface
  Concavity concavity;
  Vec3 lo, hi;
  double volume = 0.0;  // of the hull
};

// Sutherland–Hodgman: the polygon's part with n·x <= d.
void clip(std::vector<Vec3>& poly, const Plane& p, std::vector<Vec3>& scratch) {
  scratch.clear();
  const std::size_t k = poly.size();
  for (std::size_t i = 0; i < k; ++i) {
    const Vec3 &a = poly[i], &b = poly[(i + 1) % k];
    const double sa = p.n.dot(a) - p.d, sb = p.n.dot(b) - p.d;
    if (sa <= 0) scratch.push_back(a);
    if ((sa < 0 && sb > 0) || (sa > 0 && sb < 0)) scratch.push_back(a + (sa / (sa - sb)) * (b - a));
  }
  poly.swap(scratch);
}

// Corners of the cell: every triple of planes meeting in a point inside all.
std::vector<Vec3> cell_corners(const std::vector<Plane>& planes, double eps) {
  std::vector<Vec3> out;
  const std::size_t k = planes.size();
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = i + 1; j < k; ++j)
      for (std::size_t l = j + 1; l < k; ++l) {
        Eigen::Matrix3d a;
        a.row(0) = planes[i].n, a.row(1) = planes[j].n, a.row(2) = planes[l].n;
        if (std::abs(a.determinant()) < 1e-12) continue;
        const Vec3 x = a.partialPivLu().solve(Vec3(planes[i].d, planes[j].d, planes[l].d));
        bool in = true;
        for (const Plane& p : planes) in = in && p.n.dot(x) - p.d <= eps;
        if (in) out.push_back(x);
      }
  return out;
}

// A reflex (concave) edge of the closed, consistently oriented mesh: the solid
// fills more than a half-space around it. The planes of its two triangles are
// the natural cuts: on the far side of such a plane the notch is gone.
struct ReflexEdge {
  Vec3 a, b;
  std::array<int, 2> tris;
};

struct Reflex {
  std::vector<ReflexEdge> edges;
  std::vector<Plane> planes;  // per triangle (unit normal, outward)
  std::vector<int> plane_id;  // per triangle: its deduplicated plane
  std::vector<bool> concave;  // per triangle: next to a reflex edge
};

// Reflex edges of m (centred). Vertices with equal coordinates are one; edges
// that are not shared by exactly two oppositely oriented triangles are left
// out (non-manifold or inconsistently oriented: the fallback cuts handle them).
Reflex find_reflex(const Mesh& m, double eps) {
  Reflex r;
  const long nt = m.triangles.cols();
  std::map<std::array<double, 3>, int> ids;
  std::vector<int> id(m.vertices.cols());
  for (long v = 0; v < m.vertices.cols(); ++v)
    id[v] = ids.emplace(std::array<double, 3>{m.vertices(0, v), m.vertices(1, v), m.vertices(2, v)},
                        static_cast<int>(ids.size()))
                .first->second;
  double signed_volume = 0.0;
  r.planes.resize(nt);
  for (long t = 0; t < nt; ++t) {
    const Vec3 a = m.vertices.col(m.triangles(0, t)), b = m.vertices.col(m.triangles(1, t)),
               c = m.vertices.col(m.triangles(2, t));
    signed_volume += a.dot(b.cross(c));
    Vec3 n = (b - a).cross(c - a);
    n = n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
    r.planes[t] = {n, n.dot(a)};
  }
  const double sign = signed_volume >= 0 ? 1.0 : -1.0;  // outward normals
  for (Plane& p : r.planes) p = {sign * p.n, sign * p.d};
  // Directed edges: (u, v) of triangle t, the opposite corner's column.
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> directed;
  for (long t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int u = id[m.triangles(k, t)], v = id[m.triangles((k + 1) % 3, t)];
      directed[{u, v}].push_back({static_cast<int>(t), m.triangles((k + 2) % 3, t)});
    }
  r.concave.assign(nt, false);
  for (const auto& [uv, list] : directed) {
    if (uv.first > uv.second || list.size() != 1) continue;
    const auto back = directed.find({uv.second, uv.first});
    if (back == directed.end() || back->second.size() != 1) continue;
    const auto [t1, opposite1] = list[0];
    const auto [t2, opposite2] = back->second[0];
    if (r.planes[t1].n.isZero() || r.planes[t2].n.isZero()) continue;
    // Reflex when the other triangle's far corner rises above this one's plane.
    const Vec3 d = m.vertices.col(opposite2), c = m.vertices.col(opposite1);
    if (r.planes[t1].n.dot(d) - r.planes[t1].d <= eps ||
        r.planes[t2].n.dot(c) - r.planes[t2].d <= eps)
      continue;
    // The edge's coordinates: the corners of t1 other than opposite1.
    std::vector<Vec3> ends;
    for (int k = 0; k < 3; ++k)
      if (m.triangles(k, t1) != opposite1) ends.push_back(m.vertices.col(m.triangles(k, t1)));
    if (ends.size() != 2) continue;
    r.edges.push_back({ends[0], ends[1], {t1, t2}});
    r.concave[t1] = r.concave[t2] = true;
  }
  // One plane id per distinct concave plane (a hole face of two triangles, a
  // cavity wall of two, is one cut).
  r.plane_id.assign(nt, -1);
  std::vector<int> reps;
  for (long t = 0; t < nt; ++t) {
    if (!r.concave[t]) continue;
    for (int q : reps)
      if (r.planes[q].n.dot(r.planes[t].n) > 1.0 - 1e-9 &&
          std::abs(r.planes[q].d - r.planes[t].d) <= eps) {
        r.plane_id[t] = q;
        break;
      }
    if (r.plane_id[t] < 0) r.plane_id[t] = static_cast<int>(t), reps.push_back(static_cast<int>(t));
  }
  return r;
}

struct Context {
  const Mesh& m;  // centred
  const PreparedMesh& part;
  const Reflex& reflex;
  double tol, eps, void_missing;
  Clock::time_point deadline;
  long work_left;
  bool timed_out() const { return Clock::now() > deadline; }
  bool out_of_work() const { return work_left <= 0; }
  bool stop() const { return out_of_work() || timed_out(); }
};

// `hull` is hull_of_points(p.points): its volume (0 when flat), and the
// facets the piece's estimates reuse.
void finish_piece(Piece& p, const HullOfPoints& hull) {
  p.lo = p.points.rowwise().minCoeff();
  p.hi = p.points.rowwise().maxCoeff();
  p.volume = hull.facets ? hull.volume : 0.0;
}

// The part inside the cell: clipped triangles plus the cell's corners inside
// the solid (corners of cut faces), reduced to its hull's vertices. Empty when
// fewer than 4 points (nothing, or a flat sliver of surface). Its concavity is
// estimated with `samples` (one unit of work); the full estimate stops above
// `stop_above` (then the value is only a lower bound beyond it).
Piece piece_of(Context& c, const Cell& cell, int samples, const std::vector<Vec3>& probes = {},
               double stop_above = INFINITY) {
  // samples == 0: no estimate (a cell left when the time box or the budget ran
  // out); its concavity is unknown, so it counts as beyond any tolerance.
  Piece p;
  std::vector<Vec3> pts, poly, scratch;
  for (int t : cell.tris) {
    poly = {c.m.vertices.col(c.m.triangles(0, t)), c.m.vertices.col(c.m.triangles(1, t)),
            c.m.vertices.col(c.m.triangles(2, t))};
    for (const Plane& pl : cell.planes) {
      clip(poly, pl, scratch);
      if (poly.empty()) break;
    }
    if (poly.empty()) continue;
    p.tris.push_back(t);
    // A face lying in one of the cell's planes with the material outside the
    // cell is a flat sliver that would bloat the hull: left out. With the
    // material inside (a cut along a cavity wall) it bounds the piece, and its
    // corners may be vertices no other face supplies: kept. The side is probed
    // just inside the cell (orientation of soups is not trusted).
    bool flat = false;
    for (const Plane& pl : cell.planes) {
      // Only a face parallel to the plane lies in it: a face crossing it at a
      // small angle (a cut almost through a corner) is no sliver of the cut.
      if (std::abs(c.reflex.planes[t].n.dot(pl.n)) < 1.0 - 1e-6) continue;
      bool on = true;
      for (const Vec3& x : poly) on = on && std::abs(pl.n.dot(x) - pl.d) <= c.eps;
      if (!on) continue;
      Vec3 mid = Vec3::Zero();
      for (const Vec3& x : poly) mid += x / static_cast<double>(poly.size());
      flat = flat || !c.part.inside(mid - 4.0 * c.eps * pl.n);
    }
    if (!flat) {
      p.polys.push_back(
          {static_cast<long>(pts.size()), static_cast<long>(pts.size() + poly.size())});
      pts.insert(pts.end(), poly.begin(), poly.end());
    }
  }
  // Corners strictly inside the solid (a corner on the surface, where ray
  // parity is unreliable, comes from the faces through it).
  for (const Vec3& x : cell_corners(cell.planes, c.eps))
    if (c.part.inside(x) && c.part.distance(x) > c.eps) pts.push_back(x);
  if (pts.size() < 4) return p;
  Points all(3, static_cast<long>(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i) all.col(i) = pts[i];
  const Hull h = convex_hull(all);
  if (h.dimension < 3) return p;
  p.points = h.vertices;
  p.surface = std::move(all);
  const HullOfPoints hull = hull_of_points(p.points);
  finish_piece(p, hull);
  if (samples == 0) {
    p.concavity.value = INFINITY;
    return p;
  }
  // A coarse screen first (a few dozen points on the hull's facets): most cells
  // are far from convex, and any sample's distance is a lower bound, so a
  // screen beyond the tolerance decides without the full estimate.
  --c.work_left;
  // The cell's clipped faces lie on the part: samples on them are not measured.
  const SurfacePolygons faces(p.surface, p.polys, c.eps);
  const Concavity screen = hull_concavity(hull, c.part, c.tol, c.void_missing, Points(3, 0),
                                          tol::kDecomposeScreenSamples, INFINITY, &faces);
  if (screen.value > 2.0 * c.tol) {
    p.concavity = screen;
    return p;
  }
  Points probed(3, p.surface.cols() + static_cast<long>(probes.size()));
  probed << p.surface, Points::Zero(3, static_cast<long>(probes.size()));
  for (std::size_t i = 0; i < probes.size(); ++i) probed.col(p.surface.cols() + i) = probes[i];
  p.concavity =
      hull_concavity(hull, c.part, c.tol, c.void_missing, probed, samples, stop_above, &faces);
  --c.work_left;
  return p;
}

// The segment a–b clipped to the cell; false when less than eps of it is
// left, or what is left lies in one of the cell's planes (a notch the cell's
// boundary has already cut away).
bool edge_in_cell(const Context& c, const ReflexEdge& e, const Cell& cell) {
  const double eps = c.eps;
  double t0 = 0.0, t1 = 1.0;
  const Vec3 ab = e.b - e.a;
  auto centroid = [&](int t) {
    return (c.m.vertices.col(c.m.triangles(0, t)) + c.m.vertices.col(c.m.triangles(1, t)) +
            c.m.vertices.col(c.m.triangles(2, t))) /
           3.0;
  };
  for (const Plane& p : cell.planes) {
    const double sa = p.n.dot(e.a) - p.d, sb = p.n.dot(e.b) - p.d;
    if (sa > eps && sb > eps) return false;
    // In a cell plane the notch is cut away unless both its faces run into
    // the cell (a cut along the edge that kept the notch whole).
    if (std::abs(sa) <= eps && std::abs(sb) <= eps) {
      if (p.n.dot(centroid(e.tris[0])) - p.d < -eps && p.n.dot(centroid(e.tris[1])) - p.d < -eps)
        continue;
      return false;
    }
    if (sa > 0 && sb < 0) t0 = std::max(t0, sa / (sa - sb));
    if (sa < 0 && sb > 0) t1 = std::min(t1, sa / (sa - sb));
  }
  return (t1 - t0) * ab.norm() > eps;
}

// The best cut of the cell through one of its reflex edges' triangle planes:
// one that splits no concave triangle (so no new notch is made), then the one
// splitting the cell's notches most evenly (a drilled board is cut between
// its holes, not hole by hole along one side), then the one nearest the
// deepest concavity. Cuts leaving less than the tolerance on a side are
// skipped (slivers collapse piece depths). False when no plane qualifies.
bool reflex_cut(const Context& c, const Cell& cell, const Piece& p, Plane& out) {
  std::vector<int> concave, edges;
  std::vector<Plane> cand;
  for (std::size_t i = 0; i < c.reflex.edges.size(); ++i) {
    const ReflexEdge& e = c.reflex.edges[i];
    if (!std::binary_search(p.tris.begin(), p.tris.end(), e.tris[0]) &&
        !std::binary_search(p.tris.begin(), p.tris.end(), e.tris[1]))
      continue;
    if (!edge_in_cell(c, e, cell)) continue;
    edges.push_back(static_cast<int>(i));
    for (int t : e.tris) concave.push_back(t);
  }
  if (edges.empty()) return false;
  std::sort(concave.begin(), concave.end());
  concave.erase(std::unique(concave.begin(), concave.end()), concave.end());
  // Bounded effort on finely tessellated notches: a spread subset of each.
  auto thin = [](std::vector<int>& v, std::size_t most) {
    if (v.size() <= most) return;
    std::vector<int> kept;
    for (std::size_t i = 0; i < most; ++i) kept.push_back(v[i * v.size() / most]);
    v.swap(kept);
  };
  std::vector<int> planes;
  for (int t : concave) planes.push_back(c.reflex.plane_id[t]);
  std::sort(planes.begin(), planes.end());
  planes.erase(std::unique(planes.begin(), planes.end()), planes.end());
  thin(planes, tol::kDecomposeCutPlanes);
  for (int id : planes) cand.push_back(c.reflex.planes[id]);
  // Planes through two reflex edges (a fan through a hole's axis, a chord of
  // its facets): they split the notch between the sides without cutting a
  // concave face, so hole facets are shared out in halves, not peeled one by
  // one (a peel makes the cut depth grow with the facet count).
  thin(edges, tol::kDecomposeCutEdges);
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = 0; j < edges.size(); ++j) {
      if (i == j) continue;
      const ReflexEdge &e = c.reflex.edges[edges[i]], &f = c.reflex.edges[edges[j]];
      const Vec3 n = (e.b - e.a).cross(0.5 * (f.a + f.b) - e.a);
      if (n.norm() <= 1e-9 * (e.b - e.a).norm() * (f.a - e.a).norm()) continue;
      const Vec3 u = n.normalized();
      if (i < j) cand.push_back({u, u.dot(e.a)});
    }
  // Planes through a reflex edge and the deepest point of the hull's excess
  // (a fan through a hole's axis): on a half of a hole a chord would leave two
  // lumps on its inner side, a fan through the witness does not.
  const Vec3 w = p.concavity.witness;
  for (int i : edges) {
    const ReflexEdge& e = c.reflex.edges[i];
    const Vec3 n = (e.b - e.a).cross(w - e.a);
    if (n.norm() <= 1e-9 * (e.b - e.a).norm() * (w - e.a).norm()) continue;
    const Vec3 u = n.normalized();
    cand.push_back({u, u.dot(e.a)});
  }
  thin(concave, tol::kDecomposeCutFaces);
  std::tuple<int, int, double> best{INT32_MAX, 0, INFINITY};
  bool found = false;
  for (const Plane& pl : cand) {
    const Eigen::RowVectorXd s = pl.n.transpose() * p.points;
    if (s.maxCoeff() - pl.d < c.tol || pl.d - s.minCoeff() < c.tol) continue;
    int split = 0, below = 0, above = 0;
    for (int t : concave) {
      bool lo = false, hi = false;
      for (int k = 0; k < 3; ++k) {
        const double d = pl.n.dot(c.m.vertices.col(c.m.triangles(k, t))) - pl.d;
        lo = lo || d < -c.eps;
        hi = hi || d > c.eps;
      }
      split += lo && hi;
      below += lo && !hi;
      above += hi && !lo;
    }
    const std::tuple<int, int, double> key{split, -std::min(below, above),
                                           std::abs(pl.n.dot(w) - pl.d)};
    if (key < best) best = key, out = pl, found = true;
  }
  return found;
}

// A cell holding separate lumps of the part (a cut through a hole leaves one
// on each side of it): a plane in a gap of the clipped faces' projections cuts
// no face and so separates lumps exactly. Tried along the axes, the cell's own
// plane normals and the witness's direction; the widest gap wins. Costs no
// estimate.
bool lump_cut(const Context& c, const Cell& cell, const Piece& p, Plane& out) {
  std::vector<Vec3> normals{Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
  for (const Plane& pl : cell.planes) normals.push_back(pl.n);
  const Vec3 wq = p.concavity.closest - p.concavity.witness;
  if (wq.norm() > 0) {
    normals.push_back(wq.normalized());
    for (int k = 0; k < 3; ++k)
      if (wq.cross(Vec3::Unit(k)).norm() > 1e-6 * wq.norm())
        normals.push_back(wq.cross(Vec3::Unit(k)).normalized());
  }
  double widest = 2.0 * c.tol;
  bool found = false;
  std::vector<std::pair<double, double>> spans;
  for (const Vec3& n : normals) {
    spans.clear();
    for (const auto& [b, e] : p.polys) {
      const Eigen::RowVectorXd s = n.transpose() * p.surface.middleCols(b, e - b);
      spans.push_back({s.minCoeff(), s.maxCoeff()});
    }
    if (spans.size() < 2) continue;
    std::sort(spans.begin(), spans.end());
    double reach = spans[0].second;
    for (std::size_t i = 1; i < spans.size(); ++i) {
      if (spans[i].first - reach > widest) {
        widest = spans[i].first - reach;
        out = {n, 0.5 * (spans[i].first + reach)};
        found = true;
      }
      reach = std::max(reach, spans[i].second);
    }
  }
  return found;
}

// Fallback cuts (no reflex edge in the cell: separate lumps, or a mesh whose
// orientation is unknown): planes through the concavity's closest point q,
// containing the segment witness→q or normal to it, the axis planes through q
// and halving the piece's box; the one leaving the least concave pair.
bool witness_cut(Context& c, const Cell& cell, const Piece& p, Plane& out) {
  std::vector<Plane> cand;
  const Vec3 w = p.concavity.witness, q = p.concavity.closest, wq = q - w;
  const Vec3 mid = 0.5 * (p.lo + p.hi);
  for (int k = 0; k < 3; ++k) {
    const Vec3 e = Vec3::Unit(k);
    const Vec3 n = wq.cross(e);
    if (n.norm() > 1e-9 * wq.norm()) cand.push_back({n.normalized(), n.normalized().dot(q)});
    if (k == 0 && wq.norm() > 0) cand.push_back({wq.normalized(), wq.normalized().dot(q)});
    cand.push_back({e, q[k]});
    cand.push_back({e, mid[k]});
  }
  double best = INFINITY;
  for (const Plane& pl : cand) {
    if (c.stop()) break;
    const Eigen::RowVectorXd s = pl.n.transpose() * p.points;
    if (pl.d - s.minCoeff() < c.tol || s.maxCoeff() - pl.d < c.tol) continue;
    const std::vector<Vec3> probes{w, w - (pl.n.dot(w) - pl.d) * pl.n};
    Cell ca{cell.planes, p.tris, cell.depth + 1}, cb = ca;
    ca.planes.push_back(pl);
    cb.planes.push_back({-pl.n, -pl.d});
    // A piece beyond the best cost so far rules its cut out whatever the
    // other piece (cost >= either concavity): its estimate stops there, and the
    // other is not made. The same cut wins as with full estimates. (The screen
    // inside piece_of is not stopped: a full estimate may fall below it.)
    const Piece a = piece_of(c, ca, tol::kDecomposeSamples / 5, probes, best);
    if (a.concavity.value > best) continue;
    const Piece b = piece_of(c, cb, tol::kDecomposeSamples / 5, probes, best);
    if (a.points.cols() == 0 || b.points.cols() == 0) continue;
    const double cost = std::max(a.concavity.value, b.concavity.value) +
                        tol::kDecomposeBalance * p.concavity.value * std::abs(a.volume - b.volume) /
                            std::max(a.volume + b.volume, 1e-300);
    if (cost < best) best = cost, out = pl;
  }
  return std::isfinite(best);
}

Cell child(const Cell& parent, const std::vector<int>& tris, const Plane& p) {
  Cell c{parent.planes, tris, parent.depth + 1};
  c.planes.push_back(p);
  return c;
}

Points joined_points(const Points& a, const Points& b) {
  Points j(3, a.cols() + b.cols());
  j << a, b;
  return j;
}

// Merges neighbouring pieces (sharing a surface point) while the joint hull
// stays within the tolerance of the part: a hole of many facets becomes arcs
// as wide as the chord's sagitta allows. Candidates are ranked by the mean
// thickness of what the joint hull adds, (joint volume − both volumes) / joint
// area, a qhull per pair; a pair adding more than the tolerance on average is
// never tried, the others are screened, then estimated (a unit of work each).
void merge_neighbours(Context& c, std::vector<Piece>& pieces, int samples) {
  std::vector<std::unique_ptr<Piece>> all;
  std::vector<bool> live;
  std::vector<std::set<int>> near;
  std::map<std::array<long long, 3>, std::vector<int>> at;
  const double q = std::max(c.eps, 1e-12);
  for (Piece& p : pieces) {
    const int id = static_cast<int>(all.size());
    all.push_back(std::make_unique<Piece>(std::move(p)));
    live.push_back(true);
    near.emplace_back();
    std::set<std::array<long long, 3>> keys;
    for (long i = 0; i < all[id]->surface.cols(); ++i) {
      const Vec3 x = all[id]->surface.col(i) / q;
      keys.insert({std::llround(x.x()), std::llround(x.y()), std::llround(x.z())});
    }
    for (const auto& k : keys) at[k].push_back(id);
  }
  for (const auto& [k, ids] : at)
    for (int i : ids)
      for (int j : ids)
        if (i != j) near[i].insert(j);
  using Entry = std::tuple<double, int, int>;  // mean added thickness, ids
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  // The joint hulls of the ranked pairs, kept for their estimates (the same
  // qhull run: hull_of_points of the same points).
  std::map<std::pair<int, int>, HullOfPoints> joint_hulls;
  auto rank = [&](int i, int j) {
    const Piece &a = *all[i], &b = *all[j];
    HullOfPoints h = hull_of_points(joined_points(a.points, b.points));
    if (!h.facets) return;
    const double added =
        std::max(0.0, h.volume - a.volume - b.volume) / std::max(h.total_area, 1e-300);
    if (added <= c.tol) heap.push({added, i, j}), joint_hulls[{i, j}] = std::move(h);
  };
  for (std::size_t i = 0; i < all.size(); ++i)
    for (int j : near[i])
      if (static_cast<int>(i) < j) rank(static_cast<int>(i), j);
  while (!heap.empty() && !c.stop()) {
    const auto [added, i, j] = heap.top();
    heap.pop();
    auto ranked = joint_hulls.extract({i, j});
    if (!live[i] || !live[j]) continue;
    const HullOfPoints& joint_hull = ranked.mapped();
    const Points joint = joined_points(all[i]->points, all[j]->points);
    // Screen: the pieces' own hull vertices projected onto the joint hull find
    // the notch between them (a hole's vertex under the chord) at once.
    --c.work_left;
    const Points surface = joined_points(all[i]->surface, all[j]->surface);
    std::vector<std::pair<long, long>> polys = all[i]->polys;
    const long shift = all[i]->surface.cols();
    for (const auto& [b, e] : all[j]->polys) polys.push_back({b + shift, e + shift});
    const SurfacePolygons faces(surface, polys, c.eps);
    // Both estimates stop at the tolerance: a merge beyond it is refused
    // whatever the exact value, and one within it ran to the end.
    if (hull_concavity(joint_hull, c.part, c.tol, c.void_missing, joint,
                       tol::kDecomposeScreenSamples, c.tol, &faces)
            .value > c.tol)
      continue;
    const Concavity cv =
        hull_concavity(joint_hull, c.part, c.tol, c.void_missing, surface, samples, c.tol, &faces);
    --c.work_left;
    if (cv.value > c.tol) continue;
    auto u = std::make_unique<Piece>();
    u->points = convex_hull(joint).vertices;
    u->surface = surface;
    u->polys = std::move(polys);
    u->concavity = cv;
    finish_piece(*u, hull_of_points(u->points));
    const int id = static_cast<int>(all.size());
    live[i] = live[j] = false;
    std::set<int> nb;
    for (int k : near[i]) nb.insert(k);
    for (int k : near[j]) nb.insert(k);
    nb.erase(i), nb.erase(j);
    all.push_back(std::move(u));
    live.push_back(true);
    near.push_back(nb);
    for (int k : nb)
      if (live[k]) near[k].insert(id), rank(k, id);
  }
  pieces.clear();
  for (std::size_t i = 0; i < all.size(); ++i)
    if (live[i]) pieces.push_back(std::move(*all[i]));
}

// Pieces are computed in centred coordinates (the mesh's mean at the origin);
// the caller gets them back in the mesh's own.
Points uncentred(Points p, const Vec3& centre) {
  p.colwise() += centre;
  return p;
}

// The box around triangles `tris` of m, grown by `pad` on every side.
Cell root_cell(const Mesh& m, const std::vector<int>& tris, double pad) {
  Vec3 lo = Vec3::Constant(INFINITY), hi = -lo;
  for (int t : tris)
    for (int k = 0; k < 3; ++k) {
      lo = lo.cwiseMin(m.vertices.col(m.triangles(k, t)));
      hi = hi.cwiseMax(m.vertices.col(m.triangles(k, t)));
    }
  Cell cell{{}, tris, 0};
  for (int k = 0; k < 3; ++k) {
    cell.planes.push_back({Vec3::Unit(k), hi[k] + pad});
    cell.planes.push_back({-Vec3::Unit(k), -(lo[k] - pad)});
  }
  return cell;
}

// Root cells: one per shell when shells are apart (no enclosed voids, so no
// shell lies inside another), else one for the whole mesh.
std::deque<Cell> root_cells(const Context& c, const Convexity& whole, bool voids) {
  const Mesh& m = c.m;
  const double size = (m.vertices.rowwise().maxCoeff() - m.vertices.rowwise().minCoeff()).norm();
  const double pad = tol::kDecomposeRootPad * size + 4 * c.eps;  // no face lies in a root plane
  std::deque<Cell> work;
  if (whole.shells > 1 && !voids) {
    for (const std::vector<int>& tris : shell_triangles(m)) work.push_back(root_cell(m, tris, pad));
  } else {
    std::vector<int> all(m.triangles.cols());
    for (int t = 0; t < static_cast<int>(all.size()); ++t) all[t] = t;
    work.push_back(root_cell(m, all, pad));
  }
  return work;
}

// Cuts the cells in `work` breadth first until each piece is within the
// tolerance or a limit leaves it as it is: the piece count or the depth (then
// `limit_hit`, when that piece is beyond the tolerance), or nothing cutting
// it. Cells left when the time box or the work budget ran out are pieces as
// they are (covering, not necessarily within the tolerance).
std::vector<Piece> cut_cells(Context& c, std::deque<Cell> work, bool& limit_hit) {
  const int full = tol::kDecomposeSamples;
  std::vector<Piece> done;
  while (!work.empty()) {
    Cell cell = std::move(work.front());
    work.pop_front();
    Piece p = piece_of(c, cell, full);
    if (p.points.cols() == 0) continue;
    const bool limit = static_cast<int>(done.size() + work.size()) + 2 > tol::kDecomposeMaxPieces ||
                       cell.depth >= tol::kDecomposeMaxDepth;
    if (p.concavity.value <= c.tol || limit || c.stop()) {
      limit_hit = limit_hit || (p.concavity.value > c.tol && limit);
      done.push_back(std::move(p));
      continue;
    }
    Plane cut{};
    if (!reflex_cut(c, cell, p, cut) && !lump_cut(c, cell, p, cut) &&
        !witness_cut(c, cell, p, cut)) {
      done.push_back(std::move(p));  // nothing cuts it: stays concave (incomplete)
      continue;
    }
    work.push_back(child(cell, p.tris, cut));
    work.push_back(child(cell, p.tris, {-cut.n, -cut.d}));
  }
  for (Cell& cell : work) {
    Piece p = piece_of(c, cell, 0);
    if (p.points.cols()) done.push_back(std::move(p));
  }
  return done;
}

// Moves the pieces into `out` in the mesh's coordinates, with the largest
// finite concavity (an unestimated piece's is infinite: it is left out of the
// figure but not of the verdict). True when every piece is within `tol`.
bool hand_over(std::vector<Piece>& done, const Vec3& centre, double tol, Decomposition& out) {
  bool within = true;
  for (Piece& p : done) {
    within = within && p.concavity.value <= tol;
    if (std::isfinite(p.concavity.value))
      out.concavity = std::max(out.concavity, p.concavity.value);
    out.pieces.push_back(uncentred(std::move(p.points), centre));
  }
  return within;
}

// Why a decomposition is not complete, the first reason that applies.
const char* incomplete_note(const Context& c, bool limit_hit) {
  if (c.timed_out()) return "time limit reached";
  if (c.out_of_work()) return "work budget reached";
  if (limit_hit) return "piece or depth limit reached";
  return "a piece could not be cut within the tolerance";
}

}  // namespace

Decomposition decompose_convex(const Mesh& mesh, double concavity_tol, double time_limit_seconds) {
  return decompose_convex(mesh, concavity_tol, DecomposeLimits{time_limit_seconds});
}

Decomposition decompose_convex(const Mesh& mesh, double concavity_tol,
                               const DecomposeLimits& limits) {
  const auto start = Clock::now();
  Decomposition out;
  auto finish = [&]() {
    out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return out;
  };
  const Vec3 centre = mesh.vertices.rowwise().mean();
  Mesh m{mesh.vertices.colwise() - centre, mesh.triangles};
  const PreparedMesh part(m);
  const std::vector<Mesh> shells = mesh_shells(m);
  if (!part.closed()) {
    for (const Mesh& s : shells)
      out.pieces.push_back(uncentred(convex_hull(s.vertices).vertices, centre));
    out.note = "open mesh: one hull per shell";
    return finish();
  }
  // Only whether it is convex (and then its value) is used: a nonconvex
  // mesh's estimate may stop at the tolerance.
  const Convexity whole = measure_convexity(m, concavity_tol, concavity_tol);
  if (whole.convex) {
    out.pieces.push_back(uncentred(convex_hull(m.vertices).vertices, centre));
    out.complete = true;
    out.concavity = whole.concavity.value;
    out.note = "convex";
    return finish();
  }

  // Enclosed voids exist only with nested shells; without, the interior grid
  // of the concavity estimate is skipped (missing volume 0).
  const bool voids = whole.nested_shells;
  // Faces within rounding noise of a cut plane count as lying in it: float32
  // files far from the origin hold coordinates to ~2^-24 of their magnitude.
  const double eps = std::min(coordinate_noise(mesh.vertices), 0.25 * concavity_tol);
  const Reflex reflex = find_reflex(m, eps);
  const double seconds = std::min(limits.seconds, 1e7);
  Context c{
      m,
      part,
      reflex,
      concavity_tol,
      eps,
      voids ? -1.0 : 0.0,
      start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds)),
      limits.work};

  bool limit_hit = false;
  std::vector<Piece> done = cut_cells(c, root_cells(c, whole, voids), limit_hit);
  const bool stopped_early = c.stop();
  if (!stopped_early) merge_neighbours(c, done, tol::kDecomposeSamples);

  const bool within = hand_over(done, centre, concavity_tol, out);
  out.complete = within && !stopped_early;
  out.work = limits.work - c.work_left;
  if (!out.complete) out.note = incomplete_note(c, limit_hit);
  return finish();
}

}  // namespace pd
