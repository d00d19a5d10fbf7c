#include "geometry/decompose.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <map>
#include <memory>

#include "geometry/convexity.h"
#include "geometry/hull.h"
#include "geometry/mesh_intersect.h"
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

// The part inside a cell, as the vertex set of its hull.
struct Piece {
  Points points;          // hull vertices, centred coordinates
  Points surface;         // every clipped point (the part's surface in the cell)
  std::vector<int> tris;  // triangles reaching the cell
  Concavity concavity;
  Vec3 lo, hi;
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

struct Context {
  const Mesh& m;  // centred
  const PreparedMesh& part;
  double tol, eps, void_missing;
  Clock::time_point deadline;
  bool timed_out() const { return Clock::now() > deadline; }
};

// The part inside the cell: clipped triangles plus the cell's corners inside
// the solid (corners of cut faces), reduced to its hull's vertices. Empty when
// fewer than 4 points (nothing, or a flat sliver of surface).
Piece piece_of(const Context& c, const Cell& cell, int samples,
               const std::vector<Vec3>& probes = {}) {
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
    // A face lying in one of the cell's planes adds nothing: with material
    // inside the cell its corners come from the neighbouring faces, with
    // material outside it is a flat sliver that would bloat the hull.
    bool flat = false;
    for (const Plane& pl : cell.planes) {
      bool on = true;
      for (const Vec3& x : poly) on = on && std::abs(pl.n.dot(x) - pl.d) <= c.eps;
      flat = flat || on;
    }
    if (!flat) pts.insert(pts.end(), poly.begin(), poly.end());
  }
  for (const Vec3& x : cell_corners(cell.planes, c.eps))
    if (c.part.inside(x)) pts.push_back(x);
  if (pts.size() < 4) return p;
  Points all(3, static_cast<long>(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i) all.col(i) = pts[i];
  const Hull h = convex_hull(all);
  if (h.dimension < 3) return p;
  p.points = h.vertices;
  p.surface = std::move(all);
  p.lo = p.points.rowwise().minCoeff();
  p.hi = p.points.rowwise().maxCoeff();
  Points probed(3, p.surface.cols() + static_cast<long>(probes.size()));
  probed << p.surface, Points::Zero(3, static_cast<long>(probes.size()));
  for (std::size_t i = 0; i < probes.size(); ++i) probed.col(p.surface.cols() + i) = probes[i];
  p.concavity = hull_concavity(p.points, c.part, c.tol, c.void_missing, probed, samples);
  return p;
}

// Candidate cutting planes for a piece: through the concavity's closest point
// q, containing the segment witness→q (so the cut runs into the notch) or
// normal to it (the face of the notch), the axis planes through q, and the axis planes halving the
// piece's box.
std::vector<Plane> candidates(const Piece& p) {
  std::vector<Plane> out;
  const Vec3 w = p.concavity.witness, q = p.concavity.closest, wq = q - w;
  const Vec3 mid = 0.5 * (p.lo + p.hi);
  for (int k = 0; k < 3; ++k) {
    const Vec3 e = Vec3::Unit(k);
    const Vec3 n = wq.cross(e);
    if (n.norm() > 1e-9 * wq.norm()) out.push_back({n.normalized(), n.normalized().dot(q)});
    if (k == 0 && wq.norm() > 0) out.push_back({wq.normalized(), wq.normalized().dot(q)});
    out.push_back({e, q[k]});
    out.push_back({e, mid[k]});
  }
  return out;
}

Cell child(const Cell& parent, const std::vector<int>& tris, const Plane& p) {
  Cell c{parent.planes, tris, parent.depth + 1};
  c.planes.push_back(p);
  return c;
}

double box_volume(const Piece& p) {
  return (p.hi - p.lo).prod();
}

}  // namespace

Decomposition decompose_convex(const Mesh& mesh, double concavity_tol, double time_limit_seconds) {
  const auto start = Clock::now();
  Decomposition out;
  auto finish = [&]() {
    out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return out;
  };
  const Vec3 centre = mesh.vertices.rowwise().mean();
  Mesh m{mesh.vertices.colwise() - centre, mesh.triangles};
  auto to_mesh = [&](Points p) {
    p.colwise() += centre;
    return p;
  };
  const PreparedMesh part(m);
  const std::vector<Mesh> shells = mesh_shells(m);
  if (!part.closed()) {
    for (const Mesh& s : shells) out.pieces.push_back(to_mesh(convex_hull(s.vertices).vertices));
    out.note = "open mesh: one hull per shell";
    return finish();
  }
  const Convexity whole = measure_convexity(m, concavity_tol);
  if (whole.convex) {
    out.pieces.push_back(to_mesh(convex_hull(m.vertices).vertices));
    out.complete = true;
    out.concavity = whole.concavity.value;
    out.note = "convex";
    return finish();
  }

  const double size = (m.vertices.rowwise().maxCoeff() - m.vertices.rowwise().minCoeff()).norm();
  // Enclosed voids exist only with nested shells; without, the interior grid
  // of the concavity estimate is skipped (missing volume 0).
  const bool voids = whole.nested_shells;
  // Faces within rounding noise of a cut plane count as lying in it: float32
  // files far from the origin hold coordinates to ~2^-24 of their magnitude.
  const double magnitude = mesh.vertices.cwiseAbs().maxCoeff();
  const double noise = std::max(1e-9 * size, 8.0 * std::ldexp(magnitude, -24));
  Context c{m,
            part,
            concavity_tol,
            std::min(noise, 0.25 * concavity_tol),
            voids ? -1.0 : 0.0,
            start + std::chrono::duration_cast<Clock::duration>(
                        std::chrono::duration<double>(time_limit_seconds))};

  // Root cells: one per shell when shells are apart, else one for the mesh.
  std::deque<Cell> work;
  auto root = [&](const std::vector<int>& tris) {
    Vec3 lo = Vec3::Constant(INFINITY), hi = -lo;
    for (int t : tris)
      for (int k = 0; k < 3; ++k) {
        lo = lo.cwiseMin(m.vertices.col(m.triangles(k, t)));
        hi = hi.cwiseMax(m.vertices.col(m.triangles(k, t)));
      }
    const double pad = 1e-6 * size + 4 * c.eps;  // no face lies in a root plane
    Cell cell{{}, tris, 0};
    for (int k = 0; k < 3; ++k) {
      cell.planes.push_back({Vec3::Unit(k), hi[k] + pad});
      cell.planes.push_back({-Vec3::Unit(k), -(lo[k] - pad)});
    }
    work.push_back(cell);
  };
  if (whole.shells > 1 && !voids) {
    for (const std::vector<int>& tris : shell_triangles(m)) root(tris);
  } else {
    std::vector<int> all(m.triangles.cols());
    for (int t = 0; t < static_cast<int>(all.size()); ++t) all[t] = t;
    root(all);
  }

  const int full = tol::kDecomposeSamples, quick = tol::kDecomposeSamples / 5;
  std::vector<Piece> done;
  bool stopped = false;
  while (!work.empty()) {
    Cell cell = std::move(work.front());
    work.pop_front();
    Piece p = piece_of(c, cell, full);
    if (p.points.cols() == 0) continue;
    const bool limit = static_cast<int>(done.size() + work.size()) + 2 > tol::kDecomposeMaxPieces ||
                       cell.depth >= tol::kDecomposeMaxDepth;
    if (p.concavity.value <= concavity_tol || limit || c.timed_out()) {
      if (p.concavity.value > concavity_tol) stopped = true;
      done.push_back(std::move(p));
      continue;
    }
    // The cut that leaves the least concave pair of pieces (ties: the more
    // even split, so pieces do not become slivers).
    double best = INFINITY;
    Plane best_plane{};
    for (const Plane& pl : candidates(p)) {
      if (c.timed_out()) break;
      // A plane the cell already has, or one leaving a sliver thinner than the
      // tolerance, cuts nothing useful (slivers also collapse piece depths).
      const double lo = (pl.n.transpose() * p.points).minCoeff(),
                   hi = (pl.n.transpose() * p.points).maxCoeff();
      if (pl.d - lo < concavity_tol || hi - pl.d < concavity_tol) continue;
      // The parent's witness and its foot on the plane probe both children: a
      // coarse lattice alone can miss in a child the concavity the parent had.
      const Vec3 w = p.concavity.witness;
      const std::vector<Vec3> probes{w, w - (pl.n.dot(w) - pl.d) * pl.n};
      const Piece a = piece_of(c, child(cell, p.tris, pl), quick, probes);
      const Piece b = piece_of(c, child(cell, p.tris, {-pl.n, -pl.d}), quick, probes);
      if (a.points.cols() == 0 || b.points.cols() == 0) continue;
      const double va = box_volume(a), vb = box_volume(b);
      const double cost = std::max(a.concavity.value, b.concavity.value) +
                          1e-3 * p.concavity.value * std::abs(va - vb) / (va + vb);
      if (cost < best) best = cost, best_plane = pl;
    }
    if (!std::isfinite(best)) {
      stopped = true;
      done.push_back(std::move(p));
      continue;
    }
    work.push_back(child(cell, p.tris, best_plane));
    work.push_back(child(cell, p.tris, {-best_plane.n, -best_plane.d}));
  }

  // Merge neighbours (boxes within the tolerance) while the joint hull stays
  // within the tolerance, the least concave merge first. A pair's joint
  // concavity is estimated once (pieces are immutable; a merge makes a new one).
  std::vector<std::unique_ptr<Piece>> live, retired;
  for (Piece& p : done) live.push_back(std::make_unique<Piece>(std::move(p)));
  std::map<std::pair<const Piece*, const Piece*>, double> joint_cache;
  auto joint_of = [](const Piece& a, const Piece& b) {
    Points j(3, a.points.cols() + b.points.cols());
    j << a.points, b.points;
    return j;
  };
  auto joint_surface = [](const Piece& a, const Piece& b) {
    Points j(3, a.surface.cols() + b.surface.cols());
    j << a.surface, b.surface;
    return j;
  };
  while (live.size() > 1 && !c.timed_out()) {
    double best = INFINITY;
    std::size_t bi = 0, bj = 0;
    for (std::size_t i = 0; i < live.size() && !c.timed_out(); ++i)
      for (std::size_t j = i + 1; j < live.size(); ++j) {
        const Piece &a = *live[i], &b = *live[j];
        if (((a.lo.array() - concavity_tol) > b.hi.array()).any() ||
            ((b.lo.array() - concavity_tol) > a.hi.array()).any())
          continue;
        auto [it, fresh] = joint_cache.emplace(std::pair{&a, &b}, INFINITY);
        if (fresh)
          it->second = hull_concavity(joint_of(a, b), part, concavity_tol, c.void_missing,
                                      joint_surface(a, b), quick)
                           .value;
        if (it->second <= concavity_tol && it->second < best) best = it->second, bi = i, bj = j;
      }
    if (!std::isfinite(best)) break;
    const Points joint = joint_of(*live[bi], *live[bj]);
    const Points surface = joint_surface(*live[bi], *live[bj]);
    const Concavity q = hull_concavity(joint, part, concavity_tol, c.void_missing, surface, full);
    if (q.value > concavity_tol) {  // the finer estimate refuses it: never again
      joint_cache[{live[bi].get(), live[bj].get()}] = INFINITY;
      continue;
    }
    auto u = std::make_unique<Piece>();
    u->points = convex_hull(joint).vertices;
    u->surface = surface;
    u->lo = u->points.rowwise().minCoeff();
    u->hi = u->points.rowwise().maxCoeff();
    u->concavity = q;
    // Old pieces stay alive in `retired` so cached keys never alias a new piece.
    retired.push_back(std::move(live[bj]));
    retired.push_back(std::move(live[bi]));
    live.erase(live.begin() + static_cast<long>(bj));
    live[bi] = std::move(u);
  }
  done.clear();
  for (auto& p : live) done.push_back(std::move(*p));

  for (Piece& p : done) {
    out.concavity = std::max(out.concavity, p.concavity.value);
    out.pieces.push_back(to_mesh(std::move(p.points)));
  }
  out.complete = !stopped;
  if (stopped) out.note = c.timed_out() ? "time limit reached" : "piece or depth limit reached";
  return finish();
}

}  // namespace pd
