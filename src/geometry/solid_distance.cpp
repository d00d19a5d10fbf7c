#include "geometry/solid_distance.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <queue>
#include <set>
#include <stdexcept>
#include <unordered_map>

#include "geometry/convexity.h"
#include "geometry/ray_parity.h"
#include "geometry/same_position.h"
#include "geometry/triangle_tree.h"
#include "geometry/union_find.h"
#include "tolerances.h"

namespace pd {
namespace {

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// The mesh's triangles grouped into shells: triangles that share a vertex
// position (equal coordinates) are in one shell.
std::vector<Mesh> shells_of(const Mesh& mesh) {
  // Positions (welded by position) numbered in the order triangles use them.
  const std::vector<int> first = first_at_same_position(mesh.vertices);
  std::vector<int> number(first.size(), -1), id(first.size(), -1);
  int positions = 0;
  for (long t = 0; t < mesh.triangles.cols(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles(k, t);
      int& n = number[first[v]];
      if (n < 0) n = positions++;
      id[v] = n;
    }
  std::vector<int> parent(positions);
  std::iota(parent.begin(), parent.end(), 0);
  for (long t = 0; t < mesh.triangles.cols(); ++t)
    for (int k = 1; k < 3; ++k)
      parent[find_root(parent, id[mesh.triangles(k, t)])] =
          find_root(parent, id[mesh.triangles(0, t)]);
  std::map<int, std::vector<long>> groups;
  for (long t = 0; t < mesh.triangles.cols(); ++t)
    groups[find_root(parent, id[mesh.triangles(0, t)])].push_back(t);
  std::vector<Mesh> shells;
  if (groups.size() < 2) return shells;
  for (const auto& [root, tris] : groups) {
    Mesh s;
    s.vertices.resize(3, 3 * tris.size());
    s.triangles.resize(3, tris.size());
    for (size_t n = 0; n < tris.size(); ++n)
      for (int k = 0; k < 3; ++k) {
        s.vertices.col(3 * n + k) = mesh.vertices.col(mesh.triangles(k, tris[n]));
        s.triangles(k, n) = static_cast<int>(3 * n + k);
      }
    shells.push_back(std::move(s));
  }
  return shells;
}

// A triangle clipped to a box: at most 3 + 6 corners (one more per plane),
// held inline, since a plane model clips hundreds of faces.
class ClippedFace {
 public:
  ClippedFace() = default;
  // Copies hold the corners in use only.
  ClippedFace(const ClippedFace& o) : n_(o.n_) { std::copy(o.begin(), o.end(), p_.begin()); }
  ClippedFace& operator=(const ClippedFace& o) {
    n_ = o.n_;
    std::copy(o.begin(), o.end(), p_.begin());
    return *this;
  }
  const Vec3* begin() const { return p_.data(); }
  const Vec3* end() const { return p_.data() + n_; }
  size_t size() const { return n_; }
  bool empty() const { return n_ == 0; }
  const Vec3& operator[](size_t k) const { return p_[k]; }
  void clear() { n_ = 0; }
  void push_back(const Vec3& v) { p_[n_++] = v; }

 private:
  std::array<Vec3, 9> p_;
  size_t n_ = 0;
};

// The part of triangle t inside the box [lo, hi] (Sutherland–Hodgman against
// its six planes): the side tests below need only what lies near the cell, and
// a large face's far corners would fail them for no reason.
ClippedFace clip_to_box(const std::array<Vec3, 3>& t, const Vec3& lo, const Vec3& hi) {
  ClippedFace polys[2];  // the polygon and the next, by turns (no copies)
  int now = 0;
  for (const Vec3& v : t) polys[now].push_back(v);
  const auto in_box = [&](const Vec3& v) {
    return (v.array() >= lo.array()).all() && (v.array() <= hi.array()).all();
  };
  if (in_box(t[0]) && in_box(t[1]) && in_box(t[2])) return polys[now];  // the common case
  for (int axis = 0; axis < 3; ++axis)
    for (int upper = 0; upper < 2; ++upper) {
      const double bound = upper ? hi[axis] : lo[axis];
      const auto inside = [&](const Vec3& p) {
        return upper ? p[axis] <= bound : p[axis] >= bound;
      };
      const ClippedFace& poly = polys[now];
      if (std::all_of(poly.begin(), poly.end(), inside)) continue;  // this plane cuts nothing
      ClippedFace& next = polys[1 - now];
      next.clear();
      for (size_t k = 0; k < poly.size(); ++k) {
        const Vec3 &p = poly[k], &q = poly[(k + 1) % poly.size()];
        if (inside(p)) next.push_back(p);
        if (inside(p) != inside(q)) {
          const double u = (bound - p[axis]) / (q[axis] - p[axis]);
          Vec3 x = p + u * (q - p);
          x[axis] = bound;
          next.push_back(x);
        }
      }
      now = 1 - now;
      if (next.empty()) return next;
    }
  return polys[now];
}

}  // namespace

SolidDistance::SolidDistance(const Mesh& mesh) : whole_(mesh) {
  closed_ = whole_.closed();
  oriented_ = whole_.oriented();
  for (long t = 0; t < mesh.triangles.cols(); ++t)
    for (int k = 0; k < 3; ++k) box_.extend(Vec3(mesh.vertices.col(mesh.triangles(k, t))));
  noise_ = coordinate_noise(mesh.vertices);
  axes_ = whole_.face_axes();
  for (int f = 0; f < whole_.faces(); ++f)
    for (const Vec3& v : whole_.face(f)) box_in_axes_.extend(Vec3(axes_.transpose() * v));
  hair_ = 1e-9 * std::max(box_.diagonal().norm(), box_.max().cwiseAbs().maxCoeff());
  // One shell (the prepared mesh counts them as shells_of groups them): the
  // whole mesh's even-odd solid, with no regrouping to do.
  std::vector<Mesh> shells = whole_.shells() > 1 ? shells_of(mesh) : std::vector<Mesh>{};
  if (shells.empty()) {
    if (!closed_) note_ = "open mesh: no inside";
    return;
  }
  std::vector<PreparedMesh> prepared;
  prepared.reserve(shells.size());
  for (const Mesh& s : shells) prepared.emplace_back(s);
  bool meet = false;
  for (size_t i = 0; i < prepared.size() && !meet; ++i)
    for (size_t j = i + 1; j < prepared.size() && !meet; ++j)
      meet = surfaces_meet(prepared[i], prepared[j]);
  if (!meet) {  // the even-odd solid of the whole mesh (cavities are voids)
    if (!closed_) note_ = "open mesh: no inside";
    return;
  }
  // Shells that touch or overlap (multi-body exports): their union.
  exact_ = false;
  closed_ = std::all_of(prepared.begin(), prepared.end(),
                        [](const PreparedMesh& s) { return s.closed(); });
  shells_ = std::move(prepared);
  // Shells share no vertex position (shells_of), so a face's first corner
  // names its shell.
  std::vector<std::pair<std::array<double, 3>, int>> shell_at;
  shell_box_.resize(shells_.size());
  for (size_t i = 0; i < shells_.size(); ++i)
    for (int f = 0; f < shells_[i].faces(); ++f) {
      const std::array<Vec3, 3> t = shells_[i].face(f);
      for (const Vec3& v : t) shell_box_[i].extend(Vec3(axes_.transpose() * v));
      shell_at.push_back({{t[0].x(), t[0].y(), t[0].z()}, static_cast<int>(i)});
    }
  // Widened by the rounding of taking points into the axes.
  const double pad =
      tol::kFrameRounding * (box_.min().cwiseAbs().maxCoeff() + box_.max().cwiseAbs().maxCoeff());
  for (Eigen::AlignedBox3d& b : shell_box_) b.min().array() -= pad, b.max().array() += pad;
  std::sort(shell_at.begin(), shell_at.end());
  for (int f = 0; f < whole_.faces(); ++f) {
    const Vec3 v = whole_.face(f)[0];
    const std::array<double, 3> key{v.x(), v.y(), v.z()};
    const auto it = std::lower_bound(shell_at.begin(), shell_at.end(), std::pair{key, -1});
    if (it == shell_at.end() || it->first != key)  // the same triangles, welded alike
      throw std::logic_error("a face of the whole mesh is in none of its shells");
    shell_of_whole_face_.push_back(it->second);
  }
  note_ = closed_
              ? std::to_string(shells_.size()) + " shells whose surfaces meet: taken as their union"
              : "open shell: no inside";
}

DistanceBounds SolidDistance::at(const Vec3& p, int* near_face, bool upper) const {
  DistanceBounds r;
  Vec3 normal = Vec3::Zero();
  if (exact_) {
    r.lower = r.upper = whole_.signed_distance(p, &r.nearest, &normal, near_face);
    return r;
  }
  // A union: the shells' own tests say inside, not the soup's parity.
  int face = near_face ? *near_face : -1, side = 0;
  const double d = whole_.unsigned_distance(p, &r.nearest, &normal, &face, &side);
  if (near_face) *near_face = face;
  const bool inside = closed_ && inside_union(p, face, side);
  // Inside the union: every triangle is at least as near as the union's
  // surface (shared faces are not surface), so d is a lower bound. It is also
  // one from above, up to a hair, where the nearest point is union surface:
  // a point a hair outside its face that lies outside every shell is a point
  // of the complement (the ray tests are exact).
  r.lower = inside ? d : -d;
  r.upper = inside ? INFINITY : -d;
  if (upper && inside && normal.allFinite() && normal.norm() > 0) {
    const Vec3 y = r.nearest + hair_ * normal;
    if (outside_every_shell(y)) r.upper = (y - p).norm();
  }
  return r;
}

namespace {

// Each shell's side of p, in `sides` (the stack's for a few shells).
template <class Use>
auto with_shell_sides(const PreparedMesh& whole, const std::vector<int>& face_shell, const Vec3& p,
                      size_t shells, const Use& use) {
  std::array<RaySide, 16> few;
  std::vector<RaySide> many(shells > few.size() ? shells : 0);
  RaySide* sides = shells > few.size() ? many.data() : few.data();
  whole.shell_sides(p, face_shell, sides, shells);
  return use(sides);
}

}  // namespace

bool SolidDistance::inside_some_shell(const Vec3& p) const {
  return with_shell_sides(whole_, shell_of_whole_face_, p, shells_.size(),
                          [&](const RaySide* sides) {
                            for (size_t i = 0; i < shells_.size(); ++i)
                              if (shells_[i].closed() && sides[i] == RaySide::kInside) return true;
                            return false;
                          });
}

bool SolidDistance::inside_union(const Vec3& p, int face, int side) const {
  const int s = face >= 0 && side != 0 ? shell_of_whole_face_[face] : -1;
  if (s >= 0 && shells_[s].oriented()) {
    if (side < 0) return true;  // behind an outward face of its nearest point
    // Outside shell s: inside the union only inside another, so not when no
    // other shell's box holds p.
    bool other = false;
    const Vec3 y = axes_.transpose() * p;
    for (size_t i = 0; i < shells_.size() && !other; ++i)
      other = static_cast<int>(i) != s && shell_box_[i].contains(y);
    if (!other) return false;
  }
  return inside_some_shell(p);
}

bool SolidDistance::outside_every_shell(const Vec3& p) const {
  return with_shell_sides(whole_, shell_of_whole_face_, p, shells_.size(),
                          [&](const RaySide* sides) {
                            for (size_t i = 0; i < shells_.size(); ++i)
                              if (!shells_[i].closed() || sides[i] != RaySide::kOutside)
                                return false;
                            return true;
                          });
}

SurfaceDepth surface_depth(const PreparedMesh& a, const SolidDistance& b, long max_samples,
                           double only_above) {
  SurfaceDepth best;
  if (!b.closed()) return best;
  // b's box in its own face axes (y = Rᵀx): a point outside it is outside b,
  // and can be the deepest of nothing. Taken there, a part placed askew is
  // not the fat world box about it, which held much of the other part.
  const Eigen::Matrix3d& R = b.axes();
  Eigen::AlignedBox3d box = b.box_in_axes();
  {  // widened by the rounding of taking points into the axes
    const double pad = tol::kFrameRounding *
                       (b.box().min().cwiseAbs().maxCoeff() + b.box().max().cwiseAbs().maxCoeff());
    box.min().array() -= pad;
    box.max().array() += pad;
  }
  const auto local = [&](const Vec3& p) { return Vec3(R.transpose() * p); };
  const auto in_box = [&](const Vec3& p) { return box.contains(local(p)); };
  std::vector<int> faces;
  a.faces_in_turned_box(R, Vec3::Zero(), box.min(), box.max(), faces);
  int near_face = -1;  // the samples come in runs close together
  // The last point measured and its upper bound: sd is 1-Lipschitz, so no
  // point within r of it lies deeper than that bound + r. A point this shows
  // to be shallower than the deepest found (by more than the values'
  // rounding) cannot change it, and is not measured: the result is the one
  // measuring it would give.
  Vec3 last = Vec3::Zero();
  double last_upper = INFINITY;
  const double rounding = 4 * b.noise() + 1e-12 * b.box().diagonal().norm();
  const auto reach = [&](const Vec3& p) { return last_upper + (p - last).norm(); };
  const auto sample = [&](const Vec3& p) {
    const DistanceBounds d = b.at(p, &near_face, false);  // the lower bound is all it needs
    last = p;
    last_upper = d.upper;
    if (!(d.lower > best.depth)) return d.lower;
    best.depth = d.lower;
    best.at = p;
    const Vec3 dir = (p - d.nearest).normalized();
    if (dir.allFinite()) best.direction = dir;
    return d.lower;
  };
  // Every corner in b's box, once (so the bound is never below the deepest
  // vertex's, whatever the budget), then points inside the faces.
  std::set<std::array<double, 3>> corners;
  for (int f : faces)
    for (const Vec3& p : a.face(f))
      if (in_box(p) && corners.insert({p.x(), p.y(), p.z()}).second &&
          !(reach(p) < best.depth - rounding))
        sample(p);
  // Faces are split until a piece is within a quarter of b's thinnest extent
  // (a rod through a large wall face is sampled across its section); pieces
  // outside b's box are dropped, so the work follows the overlap. A piece is
  // halved across its longest edge: CAD tessellations are mostly long slivers,
  // which splitting in four would cut ever thinner across their width before
  // their length came down to the spacing (Rivara's bisection keeps the
  // pieces' shapes bounded). Each piece is sampled at its centroid and, when
  // split, at that edge's midpoint (its children's new corner). The budget goes
  // to the deepest pieces first (by their centroid's value): a part pushed deep
  // is followed down before a long contact's slivers, which stay near b's
  // surface, use the budget up.
  const double spacing = std::max(box.sizes().minCoeff() / 4, 1e-300);
  long samples = 0;
  struct Piece {
    std::array<Vec3, 3> t;
    double value;  ///< sd's lower bound at the centroid (outside b's box: a bound of it)
    double bound;  ///< of sd's lower bound over the piece
    int level;
    bool operator<(const Piece& o) const {
      return value < o.value || (value == o.value && bound < o.bound);
    }
  };
  std::priority_queue<Piece> open;
  // A piece's bound: sd's lower bound is 1-Lipschitz (a distance to the
  // triangles, its sign changing only on them), so no point of the piece
  // exceeds its value at the centroid by more than the farthest corner's
  // distance. Outside b's box, the centroid's value is a bound, not a sample.
  const auto add = [&](const std::array<Vec3, 3>& t, int level) {
    Eigen::AlignedBox3d tb(local(t[0]));
    tb.extend(local(t[1])).extend(local(t[2]));
    if (!tb.intersects(box)) return;
    const Vec3 centroid = (t[0] + t[1] + t[2]) / 3, c = local(centroid);
    // Outside b's box, sd is at most minus the distance to it: a bound as
    // good as a sample's for ordering and pruning, and free.
    double value = -std::sqrt(box.squaredExteriorDistance(c));
    const double farthest =
        std::max({(t[0] - centroid).norm(), (t[1] - centroid).norm(), (t[2] - centroid).norm()});
    if (box.contains(c)) {
      ++samples;
      // A piece the last point shows to be shallower than the deepest found
      // and than what matters is never split: measuring its centre would
      // change nothing (it is counted all the same, so the budget runs alike).
      const double r = reach(centroid);
      if (r < best.depth - rounding && r + farthest < std::max(best.depth, only_above) - rounding)
        return;
      value = sample(centroid);
    }
    open.push({t, value, value + farthest, level});
  };
  for (int f : faces) add(a.face(f), 0);
  while (!open.empty() && samples < max_samples) {
    const Piece piece = open.top();
    open.pop();
    // A piece that cannot beat the best, or reach what matters, is not split.
    if (piece.bound <= std::max(best.depth, only_above)) continue;
    const std::array<Vec3, 3>& t = piece.t;
    // Edge k runs from corner k to corner k + 1.
    const std::array<double, 3> length{(t[1] - t[0]).norm(), (t[2] - t[1]).norm(),
                                       (t[0] - t[2]).norm()};
    const int k = static_cast<int>(std::max_element(length.begin(), length.end()) - length.begin());
    // 48 halvings (2^48 pieces of a face) only stop a degenerate spacing.
    if (length[k] <= spacing || piece.level >= 48) continue;
    const Vec3 &p = t[k], &q = t[(k + 1) % 3], &o = t[(k + 2) % 3];
    const Vec3 m = 0.5 * (p + q);
    if (in_box(m)) ++samples, sample(m);
    add({p, m, o}, piece.level + 1);
    add({m, q, o}, piece.level + 1);
  }
  return best;
}

namespace {

// Where a plane model's bounds hold, and which faces it looks at
// (docs/solver.md, "Upper bound, planes"): min(sd(x), margin) at every x of
// the box c ± e of the caller's frame. A bound that would need a foot step of
// the margin or more is at least the margin, where nothing is claimed, so the
// faces within the margin of the box are all that count, and no foot point
// has to be kept anywhere. Coordinates are the frame's.
struct Region {
  Vec3 c = Vec3::Zero();
  Vec3 e = Vec3::Zero();  ///< half-extents
  double r = 0.0;         ///< half-diagonal
  double margin = 0.0;
  const RigidFrame* frame = nullptr;
  double pad = 0.0;  ///< how far taking a face into the frame may move it
  /// The largest and the least s_q over the box.
  double most(const FacePlane& q) const { return q.at(c) + e.dot(q.normal.cwiseAbs()); }
  double least(const FacePlane& q) const { return q.at(c) - e.dot(q.normal.cwiseAbs()); }
  /// The longest foot step a bound needs, given the longest its values allow.
  double step(double longest) const { return std::min(longest, margin); }
  /// Whether z lies (strictly) within the margin of the box.
  bool contains(const Vec3& z) const {
    return ((z - c).cwiseAbs().array() < (e.array() + margin)).all();
  }
  /// The box the faces are clipped to: the margin, widened for the frame's rounding.
  Vec3 lo() const { return c - e - Vec3::Constant(margin + 2 * pad); }
  Vec3 hi() const { return c + e + Vec3::Constant(margin + 2 * pad); }
  /// How far a witness point is pushed beyond the planes it tests.
  double gap(double cap) const { return 0.5 * std::min(r, margin) + 1e-3 * cap; }
  /// Where a witness's foot step may start: c, then the box's corner farthest
  /// along u (a plane beyond the box's side is nearest there).
  static constexpr int kStarts = 2;
  Vec3 start(int k, const Vec3& u) const {
    if (k == 0) return c;
    return c + Vec3(u.x() >= 0 ? e.x() : -e.x(), u.y() >= 0 ? e.y() : -e.y(),
                    u.z() >= 0 ? e.z() : -e.z());
  }
};

// A face near a box: its part within the region's clipping box, where every
// side test below is about (the certificates hold there, docs/solver.md).
struct FacePart {
  ClippedFace points;
  /// The least s_q over the face's points.
  double least(const FacePlane& q) const {
    double m = INFINITY;
    for (const Vec3& p : points) m = std::min(m, q.at(p));
    return m;
  }
  /// The greatest s_q over them.
  double greatest(const FacePlane& q) const {
    double m = -INFINITY;
    for (const Vec3& p : points) m = std::max(m, q.at(p));
    return m;
  }
};

// How deep a convex polygon reaches into the wedge {s_p < 0} ∩ {s_q < 0}: the
// largest min(−s_p, −s_q) over it. That function is concave, so its largest is
// at a corner or where the ridge s_p = s_q crosses an edge.
double wedge_crossing(const FacePart& part, const FacePlane& p, const FacePlane& q) {
  const ClippedFace& face = part.points;
  double m = -INFINITY;
  for (size_t k = 0; k < face.size(); ++k) {
    const Vec3 &x = face[k], &y = face[(k + 1) % face.size()];
    const double px = p.at(x), qx = q.at(x), py = p.at(y), qy = q.at(y);
    m = std::max(m, std::min(-px, -qx));
    const double dx = px - qx, dy = py - qy;
    if ((dx < 0) != (dy < 0)) {
      const double u = dx / (dx - dy);
      m = std::max(m, -(px + u * (py - px)));
    }
  }
  return std::min({m, -part.least(p), -part.least(q)});
}

// Face f of `mesh` taken into `frame` (FrameFaces keeps what this returns).
FrameFaces::Face face_in_frame(const PreparedMesh& mesh, int f, const RigidFrame& frame) {
  FrameFaces::Face out;
  out.corners = mesh.face(f);
  for (Vec3& v : out.corners) v = frame.local(v);
  const std::array<Vec3, 3>& t = out.corners;
  out.area = (t[1] - t[0]).cross(t[2] - t[0]);
  out.normal = out.area.normalized();
  return out;
}

// The faces near a box, grouped by plane (a quad's two triangles, a flat
// face's fan: one plane, their rounding measured as slack).
struct PlaneGroup {
  FacePlane plane;
  std::vector<FacePart> faces;
  bool supporting = true;
  Vec3 area = Vec3::Zero();  ///< the sum of its triangles' cross products (twice their vector area)
};

// The wedge of groups g and h (LocalPlanes::Wedge), if it is complement about
// the box: no face reaches more than `cap` into it, and a point of it within
// the margin (the foot point of the box's centre or corner, a little further)
// is outside the solid (`outside`, exact). W less its measured crossing, within
// the margin, is convex and holds no surface, so that one point decides all of it.
template <class Outside>
std::optional<LocalPlanes::Wedge> wedge_of(const PlaneGroup& g, const PlaneGroup& h,
                                           const std::vector<PlaneGroup>& groups, double cap,
                                           const Region& rg, const Outside& outside) {
  const Vec3 mean = (g.plane.normal + h.plane.normal).normalized();
  const double cos_spread = g.plane.normal.dot(mean);
  if (!mean.allFinite() || !(cos_spread * tol::kLocalPlanesMaxKappa >= 1.0)) return std::nullopt;
  LocalPlanes::Wedge w{g.plane, h.plane, 1.0 / cos_spread, 0.0};
  for (const PlaneGroup& f : groups)
    for (const auto& t : f.faces) {
      const double x = wedge_crossing(t, g.plane, h.plane);
      if (x > cap) return std::nullopt;
      w.slack = std::max(w.slack, x);
    }
  // The witness: a start's own foot point, a little further in.
  const double gap = rg.gap(cap);
  for (int k = 0; k < Region::kStarts; ++k) {
    const Vec3 x = rg.start(k, mean);
    const double sigma = std::max(g.plane.at(x), h.plane.at(x));
    const Vec3 z = x + w.kappa * std::max(sigma + w.slack + gap, gap) * mean;
    if (g.plane.at(z) < -w.slack && h.plane.at(z) < -w.slack && rg.contains(z))
      return outside(z) ? std::optional<LocalPlanes::Wedge>(w) : std::nullopt;
  }
  return std::nullopt;
}

// A convex hole among the non-supporting groups (LocalPlanes::hole): each of
// its faces on the outer side of the others' planes, every other face on the
// inner side of one of them, and the planes the feet do not move against
// ("far") behind every foot within the margin. Sets out's hole (the near
// planes), kappa and slack when it is one.
// With `witness` (a union of shells, where just outside one shell's face may
// be inside another), a foot point within the margin must also be outside.
template <class Outside>
std::optional<LocalPlanes::Hole> convex_hole(const std::vector<PlaneGroup>& groups,
                                             const std::vector<const PlaneGroup*>& hole,
                                             double slack, double cap, const Region& rg,
                                             bool witness, const Outside& outside) {
  using Group = PlaneGroup;
  const Vec3& c = rg.c;
  double hole_slack = slack;
  for (const Group* g : hole) {
    for (const auto& t : g->faces) hole_slack = std::max(hole_slack, -t.least(g->plane));
    for (const Group* h : hole) {
      if (g == h) continue;
      for (const auto& t : g->faces) {
        const double m = -t.greatest(h->plane);
        if (m < -cap) return std::nullopt;
        hole_slack = std::max(hole_slack, -m);
      }
    }
  }
  for (const Group& g : groups) {
    if (std::find(hole.begin(), hole.end(), &g) != hole.end()) continue;
    for (const auto& t : g.faces) {
      double best = -INFINITY;
      for (const Group* h : hole) {
        best = std::max(best, t.least(h->plane));
        if (best >= -std::min(hole_slack, cap)) break;  // settled: nothing would change
      }
      if (best < -cap) return std::nullopt;
      hole_slack = std::max(hole_slack, -best);
    }
  }
  // The feet move along m: the mean of every hole normal when they lie within
  // the largest spread of it, else (a small hole wholly within the margin, a
  // wide arc of a bore) the mean of those facing c, the ones c lies deepest
  // behind. The planes within the spread of m ("near") enter the bound; every
  // other ("far") must stay behind every foot point the box can have.
  Vec3 mean = Vec3::Zero();
  for (const Group* g : hole) mean += g->plane.normal;
  mean.normalize();
  const auto spread = [&](const Vec3& m) {
    double cos_spread = 1.0;
    for (const Group* g : hole) cos_spread = std::min(cos_spread, g->plane.normal.dot(m));
    return cos_spread;
  };
  // The mean leans towards the side with more planes (a bore's facets against
  // the one shoulder plane at its end): the bisector of the two normals
  // farthest apart spreads less when the others lie between them.
  {
    const Group *u = nullptr, *v = nullptr;
    double least = 2.0;
    for (size_t i = 0; i < hole.size(); ++i)
      for (size_t j = i + 1; j < hole.size(); ++j) {
        const double d = hole[i]->plane.normal.dot(hole[j]->plane.normal);
        if (d < least) least = d, u = hole[i], v = hole[j];
      }
    if (u) {
      const Vec3 bisector = (u->plane.normal + v->plane.normal).normalized();
      if (bisector.allFinite() && spread(bisector) > spread(mean)) mean = bisector;
    }
  }
  if (!(spread(mean) * tol::kLocalPlanesMaxKappa >= 1.0)) {
    const Group* facing = *std::max_element(hole.begin(), hole.end(), [&](auto* x, auto* y) {
      return x->plane.at(c) < y->plane.at(c);
    });
    mean = Vec3::Zero();
    for (const Group* g : hole)
      if (g->plane.normal.dot(facing->plane.normal) >= tol::kLocalPlanesFacingCos)
        mean += g->plane.normal;
    mean.normalize();
  }
  std::vector<const Group*> near, far;
  for (const Group* g : hole)
    (g->plane.normal.dot(mean) * tol::kLocalPlanesMaxKappa >= 1.0 ? near : far).push_back(g);
  if (near.empty() || !mean.allFinite()) return std::nullopt;
  double cos_spread = 1.0, most = -INFINITY;
  for (const Group* g : near) {
    cos_spread = std::min(cos_spread, g->plane.normal.dot(mean));
    most = std::max(most, rg.most(g->plane));
  }
  const double kappa = 1.0 / cos_spread;
  // The farthest foot step.
  const double longest = rg.step(kappa * std::max(most + hole_slack, 0.0));
  for (const Group* g : far)
    if (rg.most(g->plane) + longest * std::max(0.0, -g->plane.normal.dot(mean)) > -hole_slack)
      return std::nullopt;
  if (witness) {
    const double gap = rg.gap(cap);
    std::optional<Vec3> found;
    for (int k = 0; k < Region::kStarts && !found; ++k) {
      const Vec3 x = rg.start(k, mean);
      double sigma = -INFINITY;
      for (const Group* g : near) sigma = std::max(sigma, g->plane.at(x));
      const Vec3 z = x + kappa * std::max(sigma + hole_slack + gap, gap) * mean;
      if (rg.contains(z) && std::all_of(hole.begin(), hole.end(), [&](const Group* g) {
            return g->plane.at(z) < -hole_slack;
          }))
        found = z;
    }
    if (!found || !outside(*found)) return std::nullopt;
  }
  LocalPlanes::Hole out{{}, kappa, hole_slack};
  for (const Group* g : near) out.planes.push_back(g->plane);
  return out;
}

// The non-supporting groups split into holes: groups joined when each one's
// faces lie on the other's outer side (a convex hole's facets face each
// other; two holes' facets lie behind each other's planes).
std::vector<std::vector<const PlaneGroup*>> separate_holes(
    const std::vector<const PlaneGroup*>& hole, double cap) {
  const auto outer = [&](const PlaneGroup* g, const PlaneGroup* h) {
    for (const auto& t : g->faces) {
      if (t.greatest(h->plane) > cap) return false;
    }
    return true;
  };
  UnionFind sets(hole.size());
  for (size_t i = 0; i < hole.size(); ++i)
    for (size_t j = i + 1; j < hole.size(); ++j)
      // Joined already (through others): the sets would not change.
      if (sets.find(i) != sets.find(j) && outer(hole[i], hole[j]) && outer(hole[j], hole[i]))
        sets.join(i, j);
  std::vector<std::vector<const PlaneGroup*>> out;
  std::vector<int> slot(hole.size(), -1);
  for (size_t i = 0; i < hole.size(); ++i) {
    int& k = slot[sets.find(i)];
    if (k < 0) k = static_cast<int>(out.size()), out.emplace_back();
    out[k].push_back(hole[i]);
  }
  return out;
}

// Each group's plane fitted to all its faces: the normal of their summed
// vector area, the offset of the outermost of their points. A group is
// gathered about its first face's plane, and a sliver's plane is ill-posed:
// float32 corners far from the origin tilt a thin triangle's normal by their
// rounding over its width, and the other faces then cross that plane by up to
// the cap, which every bound of the plane pays as slack. The summed area
// averages the tilt out over the whole face. Any plane serves: every
// certificate measures its faces against the plane it is given, own faces
// included (docs/solver.md); these measure far less (the ball bearing's seated
// rings settled with a tenth of the boxes).
void fit_planes(std::vector<PlaneGroup>& groups) {
  for (PlaneGroup& g : groups) {
    const Vec3 n = g.area.normalized();
    if (!n.allFinite()) continue;  // keeps its first face's plane
    double offset = -INFINITY;
    for (const FacePart& t : g.faces)
      for (const Vec3& p : t.points) offset = std::max(offset, n.dot(p));
    g.plane = {n, offset};
  }
}

// The faces of `mesh` (world coordinates) taken into the region's frame (or
// found there in `memo`), clipped to its box and grouped by plane (within
// `cap`), each group's plane fitted to its faces; nullopt when a face has no
// normal (degenerate).
std::optional<std::vector<PlaneGroup>> groups_near(const PreparedMesh& mesh,
                                                   const std::vector<int>& faces, const Region& rg,
                                                   double cap, FrameFaces* memo) {
  const Vec3 box_lo = rg.lo(), box_hi = rg.hi();
  std::vector<PlaneGroup> groups;
  // The groups by normal cell: a face joins a group whose normal is within
  // 0.999 of its own (2.6°), so within 0.0448 of it on every axis, and the
  // cells of side 0.05 that its normal ± kReach meets hold every such group:
  // one or two a side, against the 27 about its own cell. (A curved surface
  // makes a group of nearly every face: a scan of all groups would be
  // quadratic.)
  constexpr double kCell = 0.05, kReach = 0.045;
  using Cell = std::array<int, 3>;
  const auto cell_of = [](const Vec3& n) {
    return Cell{static_cast<int>(std::floor(n.x() / kCell)),
                static_cast<int>(std::floor(n.y() / kCell)),
                static_cast<int>(std::floor(n.z() / kCell))};
  };
  // A unit normal's cells lie within ±21 on each axis: one integer each.
  const auto key_of = [](const Cell& c) {
    return (std::int64_t(c[0] + 64) << 16) | (std::int64_t(c[1] + 64) << 8) |
           std::int64_t(c[2] + 64);
  };
  // Few groups (a box's few flat faces, the common case) are scanned in
  // order, which finds the same group as the cells (the first that holds the
  // face) for less than the cells' hashing: the cells are made only once
  // there are more than kScan groups.
  constexpr size_t kScan = 32;
  std::unordered_map<std::int64_t, std::vector<size_t>> by_cell;
  size_t last = 0;
  FrameFaces::Face own;
  for (int f : faces) {
    if (!memo) own = face_in_frame(mesh, f, *rg.frame);
    const FrameFaces::Face& face = memo ? (*memo)[f] : own;
    const std::array<Vec3, 3>& t = face.corners;
    const Vec3 &area = face.area, &n = face.normal;
    if (!n.allFinite()) return std::nullopt;
    FacePart part{clip_to_box(t, box_lo, box_hi)};
    if (part.points.empty()) continue;
    const auto same_plane = [&](const PlaneGroup& q) {
      return q.plane.normal.dot(n) > 0.999 &&
             std::all_of(part.points.begin(), part.points.end(),
                         [&](const Vec3& p) { return std::abs(q.plane.at(p)) <= cap; });
    };
    // A face's plane is most often the previous face's (a quad's two
    // triangles, a fan), so that group is asked first; else the first group
    // (in the order they were made) that holds it.
    size_t g = groups.size();
    if (last < groups.size() && same_plane(groups[last])) {
      g = last;
    } else if (groups.size() <= kScan) {
      for (size_t k = 0; k < groups.size(); ++k)
        if (k != last && same_plane(groups[k])) {
          g = k;
          break;
        }
    } else {
      if (by_cell.empty())  // the groups made so far, in order
        for (size_t k = 0; k < groups.size(); ++k)
          by_cell[key_of(cell_of(groups[k].plane.normal))].push_back(k);
      const Cell from = cell_of(n.array() - kReach), to = cell_of(n.array() + kReach);
      for (int x = from[0]; x <= to[0]; ++x)
        for (int y = from[1]; y <= to[1]; ++y)
          for (int z = from[2]; z <= to[2]; ++z) {
            const auto it = by_cell.find(key_of(Cell{x, y, z}));
            if (it == by_cell.end()) continue;
            for (size_t k : it->second)
              if (k < g && same_plane(groups[k])) g = k;
          }
    }
    if (g == groups.size()) {
      groups.push_back({{n, n.dot(t[0])}, {}, true, Vec3::Zero()});
      if (!by_cell.empty()) by_cell[key_of(cell_of(n))].push_back(g);
    }
    last = g;
    groups[g].faces.push_back(std::move(part));
    groups[g].area += area;
  }
  fit_planes(groups);
  return groups;
}

// How far any face lies beyond each group's plane (measured for the
// supporting planes, the only ones it bounds). A plane that a face crosses by
// more than cap is not supporting, and its scan stops there.
std::vector<double> measure_crossings(std::vector<PlaneGroup>& groups, double cap) {
  std::vector<double> crossing(groups.size(), 0.0);
  for (size_t k = 0; k < groups.size(); ++k)
    for (size_t h = 0; h < groups.size() && groups[k].supporting; ++h)
      for (const auto& t : groups[h].faces) {
        const double m = t.least(groups[k].plane);
        crossing[k] = std::max(crossing[k], -m);
        if (m < -cap) {
          groups[k].supporting = false;
          break;
        }
      }
  return crossing;
}

// Whether a face of group h lies beyond g's plane by more than cap.
bool crosses(const PlaneGroup& g, const PlaneGroup& h, double cap) {
  return std::any_of(h.faces.begin(), h.faces.end(),
                     [&](const FacePart& t) { return t.least(g.plane) < -cap; });
}

// Each supporting plane bounds sd on its own: the nearest ones (at most
// kLocalPlanesMaxPlanes) bound it best, and one at or above the margin
// throughout the box bounds nothing. With `witness`, a point beyond the
// plane's crossings, within the margin, must be outside.
template <class Outside>
void add_supporting(const std::vector<PlaneGroup>& groups, const std::vector<double>& crossing,
                    const Region& rg, double cap, bool witness, const Outside& outside,
                    LocalPlanes& out) {
  const Vec3& c = rg.c;
  std::vector<std::pair<double, size_t>> nearest;  // by s(c)
  for (size_t k = 0; k < groups.size(); ++k)
    if (groups[k].supporting && rg.least(groups[k].plane) + crossing[k] < rg.margin)
      nearest.push_back({groups[k].plane.at(c), k});
  std::sort(nearest.begin(), nearest.end());
  if (nearest.size() > static_cast<size_t>(tol::kLocalPlanesMaxPlanes))
    nearest.resize(tol::kLocalPlanesMaxPlanes);
  for (const auto& [s_c, k] : nearest) {
    if (witness) {
      const FacePlane& q = groups[k].plane;
      bool shown = false;  // a point beyond the crossings, outside
      for (int j = 0; j < Region::kStarts; ++j) {
        const Vec3 x = rg.start(j, q.normal);
        const double step = std::max(q.at(x), 0.0) + crossing[k] + rg.gap(cap);
        const Vec3 z = x + step * q.normal;
        if (!rg.contains(z)) continue;
        shown = outside(z);
        break;
      }
      if (!shown) continue;
    }
    out.supporting.push_back(groups[k].plane);
    out.slack = std::max(out.slack, crossing[k]);
  }
}

// One convex hole, else several apart (each holds on its own). Returns
// whether every hole plane is explained. Too many planes in one (a whole
// small hole within the margin): that hole is left out.
template <class Outside>
bool add_holes(const std::vector<PlaneGroup>& groups, const std::vector<const PlaneGroup*>& hole,
               double cap, const Region& rg, bool witness, const Outside& outside,
               LocalPlanes& out) {
  const auto one_hole = [&](const std::vector<const PlaneGroup*>& planes) {
    if (planes.size() > static_cast<size_t>(tol::kLocalPlanesMaxPlanes))
      return std::optional<LocalPlanes::Hole>();
    return convex_hole(groups, planes, out.slack, cap, rg, witness, outside);
  };
  if (auto h = one_hole(hole)) {
    out.holes.push_back(std::move(*h));
    return true;
  }
  const auto apart = separate_holes(hole, cap);
  if (apart.size() < 2) return false;
  std::vector<LocalPlanes::Hole> found;
  for (const auto& planes : apart)
    if (auto h = one_hole(planes)) found.push_back(std::move(*h));
  const bool all = found.size() == apart.size();
  for (auto& h : found) out.holes.push_back(std::move(h));
  return all;
}

// Wedges among the hole planes that bound no convex hole, the pairs with the
// smallest bound at c first. Only planes whose faces cross each other's outer
// side can make one (a concave edge's two sides; a cylinder's facets never
// cross each other).
template <class Outside>
void add_wedges(const std::vector<PlaneGroup>& groups, const std::vector<const PlaneGroup*>& hole,
                double cap, const Region& rg, const Outside& outside, LocalPlanes& out) {
  const Vec3& c = rg.c;
  std::vector<std::pair<double, std::pair<const PlaneGroup*, const PlaneGroup*>>> pairs;
  for (size_t i = 0; i < hole.size(); ++i)
    for (size_t j = i + 1; j < hole.size(); ++j) {
      const Vec3 mean = (hole[i]->plane.normal + hole[j]->plane.normal).normalized();
      const double cos_spread = hole[i]->plane.normal.dot(mean);
      if (!(cos_spread * tol::kLocalPlanesMaxKappa >= 1.0)) continue;
      if (!crosses(*hole[i], *hole[j], cap) && !crosses(*hole[j], *hole[i], cap)) continue;
      const double at_c = std::max(hole[i]->plane.at(c), hole[j]->plane.at(c)) / cos_spread;
      pairs.push_back({at_c, {hole[i], hole[j]}});
    }
  std::sort(pairs.begin(), pairs.end(),
            [](const auto& p, const auto& q) { return p.first < q.first; });
  int tries = 0;
  for (const auto& [at_c, gh] : pairs) {
    if (tries++ >= tol::kLocalPlanesWedgeTries ||
        out.wedges.size() >= static_cast<size_t>(tol::kLocalPlanesMaxWedges))
      break;
    if (auto w = wedge_of(*gh.first, *gh.second, groups, cap, rg, outside))
      out.wedges.push_back(*w);
  }
}

// The faces of `mesh` that may meet the region's box widened by its margin
// (and by the frame's rounding): all that a plane model about it looks at.
void faces_near(const PreparedMesh& mesh, const Region& rg, std::vector<int>& out,
                size_t limit = std::numeric_limits<size_t>::max()) {
  mesh.faces_in_turned_box(rg.frame->R, rg.frame->origin, rg.lo(), rg.hi(), out, limit);
}

// The plane model of one oriented closed mesh about a region;
// `outside(p)`: p (in the region's coordinates) strictly outside the solid.
template <class Outside>
LocalPlanes planes_near(const PreparedMesh& mesh, double noise, const Region& rg, bool witness,
                        const Outside& outside, FrameFaces* memo) {
  LocalPlanes out;
  out.margin = rg.margin;
  // Needles (collinear triangles, segments in PreparedMesh) are not checked:
  // in a closed mesh each lies on the edge of the face across its longest
  // side, so that face's checks cover its points.
  if (!mesh.oriented()) return out;
  // A face may cross a plane it should not by at most `cap` (the coordinates'
  // rounding) and still count as on its side; the crossings actually measured
  // become the bound's slack, so the certificate holds exactly.
  const double cap = noise + rg.pad;
  std::vector<int> near;
  faces_near(mesh, rg, near, tol::kLocalPlanesMaxFaces);
  if (near.empty() || near.size() > static_cast<size_t>(tol::kLocalPlanesMaxFaces)) return out;
  if (memo) memo->use(mesh, *rg.frame);
  auto groups = groups_near(mesh, near, rg, cap, memo);
  if (!groups) return out;
  const std::vector<double> crossing = measure_crossings(*groups, cap);
  add_supporting(*groups, crossing, rg, cap, witness, outside, out);
  std::vector<const PlaneGroup*> hole;
  for (const PlaneGroup& g : *groups)
    if (!g.supporting) hole.push_back(&g);
  // Wedges only where the holes leave planes unexplained.
  const bool explained = hole.empty() || add_holes(*groups, hole, cap, rg, witness, outside, out);
  if (!explained && hole.size() <= static_cast<size_t>(tol::kLocalPlanesMaxPlanes))
    add_wedges(*groups, hole, cap, rg, outside, out);
  // The frame's rounding: the faces looked at are within pad of the true ones.
  out.slack += rg.pad;
  for (LocalPlanes::Hole& h : out.holes) h.slack += rg.pad;
  for (LocalPlanes::Wedge& w : out.wedges) w.slack += rg.pad;
  return out;
}

// A framed box and its margin.
Region box_region(const FramedBox& box, double margin) {
  Region rg;
  rg.frame = &box.frame;
  rg.c = 0.5 * (box.lo + box.hi);
  rg.e = 0.5 * (box.hi - box.lo);
  rg.r = rg.e.norm();
  rg.margin = margin;
  Eigen::AlignedBox3d wbox;  // the world box that holds it
  const Vec3 lo = box.lo.array() - margin, hi = box.hi.array() + margin;
  for (int k = 0; k < 8; ++k)
    wbox.extend(box.frame.world(
        Vec3(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z())));
  // Taking a face into the frame rounds it by up to pad; the faces are
  // gathered that much wider (Region::lo, hi) and every slack grows by it.
  rg.pad = 16 * std::numeric_limits<double>::epsilon() *
           (wbox.max().cwiseAbs().maxCoeff() + wbox.min().cwiseAbs().maxCoeff() +
            box.frame.origin.cwiseAbs().maxCoeff());
  return rg;
}

// A union of shells about a region (centre c_world): where one shell alone
// has faces there and the centre lies outside every other shell, the union is
// that shell there. Elsewhere every shell's faces count, and each
// plane, hole and wedge must show a point of its outer side that is outside
// every shell (exact ray tests): just outside one shell's face may be inside
// another.
template <class Outside>
LocalPlanes union_planes(const std::vector<PreparedMesh>& shells, const PreparedMesh& whole,
                         double noise, const Region& rg, const Vec3& c_world,
                         const Outside& outside_all, FrameFaces* memo) {
  int alone = -1;
  bool several = false;
  std::vector<int> near;
  for (size_t i = 0; i < shells.size() && !several; ++i) {
    near.clear();
    faces_near(shells[i], rg, near);
    if (near.empty()) continue;
    several = alone >= 0;
    alone = static_cast<int>(i);
  }
  if (alone < 0) {
    LocalPlanes none;
    none.margin = rg.margin;
    return none;
  }
  if (!several) {
    bool others_outside = true;
    for (size_t i = 0; i < shells.size() && others_outside; ++i)
      others_outside = static_cast<int>(i) == alone || shells[i].outside(c_world);
    // The memo follows one mesh: the whole's faces, asked far more often.
    if (others_outside) return planes_near(shells[alone], noise, rg, false, outside_all, nullptr);
  }
  return planes_near(whole, noise, rg, true, outside_all, memo);
}

}  // namespace

LocalPlanes SolidDistance::local_planes(const FramedBox& box, double margin,
                                        FrameFaces* faces) const {
  const Region rg = box_region(box, margin);
  if (exact_) {
    const auto outside = [&](const Vec3& y) { return whole_.outside(box.frame.world(y)); };
    return planes_near(whole_, noise_, rg, false, outside, faces);
  }
  const auto outside_all = [&](const Vec3& y) { return outside_every_shell(box.frame.world(y)); };
  return union_planes(shells_, whole_, noise_, rg, box.frame.world(rg.c), outside_all, faces);
}

void FrameFaces::use(const PreparedMesh& mesh, const RigidFrame& frame) {
  if (mesh_ == &mesh && frame_.origin == frame.origin && frame_.R == frame.R) return;
  mesh_ = &mesh;
  frame_ = frame;
  faces_.clear();
  slot_.assign(static_cast<size_t>(mesh.faces()), 0);
}

const FrameFaces::Face& FrameFaces::operator[](int f) {
  int& slot = slot_[static_cast<size_t>(f)];
  if (slot == 0) {
    faces_.push_back(face_in_frame(*mesh_, f, frame_));
    slot = static_cast<int>(faces_.size());
  }
  return faces_[static_cast<size_t>(slot - 1)];
}

}  // namespace pd
