#include "geometry/mesh_intersect.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/huge_page_allocator.h"
#include "geometry/ray_parity.h"
#include "geometry/same_position.h"
#include "geometry/triangle_tree.h"
#include "tolerances.h"

namespace pd {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = K::Point_3;
using Triangle3 = K::Triangle_3;
using Segment3 = K::Segment_3;

int find_root(HugeVector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

struct PreparedMesh::Impl {
  HugeVector<Point3> points;       // merged: equal coordinates are one point
  HugeVector<int> merged;          // original column -> index into points, -1 if unused
  int faces = 0;                   // non-degenerate triangles: the tree's (`search`)
  std::vector<Segment3> segments;  // degenerate (collinear) triangles as their hull
  std::vector<int> shell_vertex;   // one merged vertex per connected component
  bool closed = false;
  CGAL::Bbox_3 box;
  TriangleTree search;    // over faces: nearest points, box listings and ray tests
  bool parity = false;    // closed and has faces: points can be located
  bool oriented = false;  // closed, each edge as often u→v as v→u, outward (volume > 0)

  // Meaningful on closed meshes only (parity).
  RaySide side(const Point3& p) const {
    return ray_parity_side(search, Vec3(box.xmin(), box.ymin(), box.zmin()),
                           Vec3(box.xmax(), box.ymax(), box.zmax()), Vec3(p.x(), p.y(), p.z()));
  }

  // Face i's corners as CGAL's triangle (for its exact predicates).
  Triangle3 face(int i) const {
    const std::array<Vec3, 3>& t = search.triangle(i);
    return {Point3(t[0].x(), t[0].y(), t[0].z()), Point3(t[1].x(), t[1].y(), t[1].z()),
            Point3(t[2].x(), t[2].y(), t[2].z())};
  }

  // Closest point of the surface to p (faces and degenerate segments).
  Point3 closest(const Point3& p) const {
    Point3 best = p;
    double best_d2 = INFINITY;
    if (faces > 0) {
      const Vec3 q = search.nearest(Vec3(p.x(), p.y(), p.z())).point;
      best = Point3(q.x(), q.y(), q.z());
      best_d2 = CGAL::squared_distance(p, best);
    }
    for (const Segment3& s : segments) {
      const double d2 = CGAL::squared_distance(p, s);
      if (d2 < best_d2) {
        // The projection onto the segment, clamped to its ends.
        const K::Vector_3 d = s.target() - s.source();
        double t = ((p - s.source()) * d) / d.squared_length();
        t = std::clamp(t, 0.0, 1.0);
        best = s.source() + t * d;
        best_d2 = d2;
      }
    }
    return best;
  }
};

PreparedMesh::PreparedMesh(const Mesh& mesh) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  const long n = mesh.vertices.cols();
  if (mesh.triangles.cols() == 0) throw std::invalid_argument("mesh has no triangles");
  for (long t = 0; t < mesh.triangles.cols(); ++t)
    for (int k = 0; k < 3; ++k)
      if (mesh.triangles(k, t) < 0 || mesh.triangles(k, t) >= n)
        throw std::invalid_argument("triangle " + std::to_string(t) + " indexes vertex " +
                                    std::to_string(mesh.triangles(k, t)) + " of " +
                                    std::to_string(n));

  // Merge vertices with equal coordinates (STL stores each triangle's corners),
  // numbered in the order the triangles first use them.
  m.merged.assign(n, -1);
  const std::vector<int> first = first_at_same_position(mesh.vertices);
  HugeVector<int> point_of(n, -1);  // by a position's first column
  // Sized once (a large part's vectors would otherwise be copied as they grow).
  size_t positions = 0;
  for (long v = 0; v < n; ++v) positions += first[size_t(v)] == v;
  m.points.reserve(positions);
  HugeVector<std::array<Vec3, 3>> corners;  // of the faces: the tree's
  corners.reserve(size_t(mesh.triangles.cols()));
  for (long t = 0; t < mesh.triangles.cols(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles(k, t);
      if (m.merged[v] >= 0) continue;
      if (!mesh.vertices.col(v).allFinite())
        throw std::invalid_argument("vertex " + std::to_string(v) + " is not finite");
      int& at = point_of[first[v]];
      if (at < 0) {
        at = static_cast<int>(m.points.size());
        m.points.emplace_back(mesh.vertices(0, v), mesh.vertices(1, v), mesh.vertices(2, v));
      }
      m.merged[v] = at;
    }

  // Edge parity (closedness), shells and the two primitive sets. Each use of
  // an edge is listed (its ends in order, +1 when walked from the lower end);
  // sorted, the uses of one edge are a run.
  HugeVector<int> parent(m.points.size());
  std::iota(parent.begin(), parent.end(), 0);
  struct EdgeUse {
    int lo, hi, sign;
    bool operator<(const EdgeUse& o) const { return lo != o.lo ? lo < o.lo : hi < o.hi; }
  };
  HugeVector<EdgeUse> uses;
  uses.reserve(3 * static_cast<size_t>(mesh.triangles.cols()));
  for (long t = 0; t < mesh.triangles.cols(); ++t) {
    const int i = m.merged[mesh.triangles(0, t)], j = m.merged[mesh.triangles(1, t)],
              k = m.merged[mesh.triangles(2, t)];
    parent[find_root(parent, j)] = find_root(parent, i);
    parent[find_root(parent, k)] = find_root(parent, i);
    // A triangle with a repeated corner is an edge traversed twice: no parity.
    if (i == j || j == k || k == i) {
      const int a = std::min({i, j, k}), b = std::max({i, j, k});
      if (a != b) m.segments.emplace_back(m.points[a], m.points[b]);
      continue;
    }
    for (auto [u, w] : {std::pair{i, j}, std::pair{j, k}, std::pair{k, i}})
      uses.push_back({std::min(u, w), std::max(u, w), u < w ? 1 : -1});
    const Point3 &p = m.points[i], &q = m.points[j], &r = m.points[k];
    if (!CGAL::collinear(p, q, r)) {
      corners.push_back(
          {Vec3(p.x(), p.y(), p.z()), Vec3(q.x(), q.y(), q.z()), Vec3(r.x(), r.y(), r.z())});
    } else {
      // A needle: the segment between its two farthest corners covers it.
      const double pq = CGAL::squared_distance(p, q), qr = CGAL::squared_distance(q, r),
                   rp = CGAL::squared_distance(r, p);
      if (pq >= qr && pq >= rp)
        m.segments.emplace_back(p, q);
      else if (qr >= rp)
        m.segments.emplace_back(q, r);
      else
        m.segments.emplace_back(r, p);
    }
  }
  // Closed: every edge used an even number of times. Oriented as well: each
  // walked as often one way as the other, and the volume positive (outward).
  // The uses put in order of their lower end by counting, then each vertex's
  // few by their upper end: the uses of one edge are a run.
  {
    HugeVector<size_t> start(m.points.size() + 1, 0);
    for (const EdgeUse& u : uses) ++start[size_t(u.lo) + 1];
    for (size_t v = 0; v < m.points.size(); ++v) start[v + 1] += start[v];
    HugeVector<EdgeUse> by_lo(uses.size());
    HugeVector<size_t> next(start.begin(), start.end() - 1);
    for (const EdgeUse& u : uses) by_lo[next[size_t(u.lo)]++] = u;
    for (size_t v = 0; v < m.points.size(); ++v)
      std::sort(by_lo.begin() + std::ptrdiff_t(start[v]),
                by_lo.begin() + std::ptrdiff_t(start[v + 1]));
    uses = std::move(by_lo);
  }
  bool even = !uses.empty(), balanced = true;
  for (size_t a = 0, b = 0; a < uses.size(); a = b) {
    int count = 0, balance = 0;
    for (b = a; b < uses.size() && uses[b].lo == uses[a].lo && uses[b].hi == uses[a].hi; ++b) {
      ++count;
      balance += uses[b].sign;
    }
    even = even && count % 2 == 0;
    balanced = balanced && balance == 0;
  }
  double volume = 0.0;
  const Point3& o = m.points[0];
  for (const std::array<Vec3, 3>& c : corners) {
    const Point3 f0(c[0].x(), c[0].y(), c[0].z()), f1(c[1].x(), c[1].y(), c[1].z()),
        f2(c[2].x(), c[2].y(), c[2].z());
    volume += CGAL::scalar_product(f0 - o, CGAL::cross_product(f1 - o, f2 - o));
  }
  m.oriented = volume > 0 && balanced;
  m.closed = even;
  for (int v = 0; v < static_cast<int>(m.points.size()); ++v)
    if (find_root(parent, v) == v) m.shell_vertex.push_back(v);

  m.box = CGAL::bbox_3(m.points.begin(), m.points.end());
  // The tree keeps the faces' corners (in its order): the only copy of them.
  m.faces = static_cast<int>(corners.size());
  if (m.faces > 0) m.search = TriangleTree(corners.data(), corners.size());
  m.parity = m.closed && m.faces > 0;
}

PreparedMesh::~PreparedMesh() = default;
PreparedMesh::PreparedMesh(PreparedMesh&&) noexcept = default;
PreparedMesh& PreparedMesh::operator=(PreparedMesh&&) noexcept = default;
bool PreparedMesh::closed() const {
  return impl_->parity;
}
int PreparedMesh::shells() const {
  return static_cast<int>(impl_->shell_vertex.size());
}

double PreparedMesh::distance(const Vec3& v) const {
  const Point3 p(v.x(), v.y(), v.z());
  return std::sqrt(CGAL::squared_distance(p, impl_->closest(p)));
}

Vec3 PreparedMesh::closest_point(const Vec3& v) const {
  const Point3 q = impl_->closest(Point3(v.x(), v.y(), v.z()));
  return {q.x(), q.y(), q.z()};
}

double PreparedMesh::outside_distance(const Vec3& v) const {
  Hint none;
  return outside_distance(v, none);
}

namespace {

// Which side of its nearest face p lies on, from its nearest point q on face
// `face` (squared distance d2): +1 the side the face's corner order points to,
// -1 the other, 0 when the nearest face cannot tell (q on an edge or vertex, or
// a degenerate segment as near), and only a ray test can. Exact when q lies
// strictly inside the face: the segment p–q then crosses no other face, so p
// is on that side of every closed shell the face belongs to.
int face_side(const PreparedMesh::Impl& m, const Vec3& v, const Point3& q, int face, double d2) {
  bool decided = d2 > 0;
  for (const Segment3& s : m.segments)
    decided = decided && CGAL::squared_distance(Point3(v.x(), v.y(), v.z()), s) > d2;
  if (!decided) return 0;
  // Barycentric coordinates of q in the nearest face: strictly inside it?
  const std::array<Vec3, 3>& t = m.search.triangle(face);
  const Vec3 &a = t[0], &b = t[1], &c = t[2], x(q.x(), q.y(), q.z());
  const Vec3 e0 = b - a, e1 = c - a, e2 = x - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1), d20 = e2.dot(e0),
               d21 = e2.dot(e1), den = d00 * d11 - d01 * d01;
  const double l1 = (d11 * d20 - d01 * d21) / den, l2 = (d00 * d21 - d01 * d20) / den;
  const double margin = tol::kNearestFaceMargin;
  if (!(den > 0 && l1 > margin && l2 > margin && 1 - l1 - l2 > margin)) return 0;
  return e0.cross(e1).dot(Vec3(v - x)) > 0 ? 1 : -1;
}

// The side of an oriented closed mesh p lies on: +1 outside, -1 inside, 0
// when its nearest face cannot tell or the orientation is unknown.
int nearest_face_side(const PreparedMesh::Impl& m, const Vec3& v, const Point3& q, int face,
                      double d2) {
  return m.oriented ? face_side(m, v, q, face, d2) : 0;
}

}  // namespace

double PreparedMesh::outside_distance(const Vec3& v, Hint& hint) const {
  const Impl& m = *impl_;
  const Point3 p(v.x(), v.y(), v.z());
  if (!m.parity) return distance(v);
  const auto inside_here = [&] {
    hint.inside_point = v;
    hint.has_inside = true;
    return 0.0;
  };
  // Joined to an inside point without crossing the surface: inside too.
  if (hint.has_inside && !segment_meets_triangles(m.search, hint.inside_point, v))
    return inside_here();
  hint.has_inside = false;
  const TriangleTree::Nearest n = m.search.nearest(v, static_cast<int>(hint.face));
  const Point3 q(n.point.x(), n.point.y(), n.point.z());
  const int face = n.face;
  hint.point = n.point;
  hint.face = n.face;
  const double d2 = CGAL::squared_distance(p, q);
  const int side = nearest_face_side(m, v, q, face, d2);
  if (side != 0) return side > 0 ? std::sqrt(d2) : inside_here();
  return m.side(p) == RaySide::kInside ? inside_here() : distance(v);
}

bool PreparedMesh::inside(const Vec3& v) const {
  return impl_->parity && impl_->side(Point3(v.x(), v.y(), v.z())) == RaySide::kInside;
}

bool PreparedMesh::outside(const Vec3& v) const {
  return impl_->parity && impl_->side(Point3(v.x(), v.y(), v.z())) == RaySide::kOutside;
}

bool PreparedMesh::oriented() const {
  return impl_->parity && impl_->oriented;
}

bool PreparedMesh::has_segments() const {
  return !impl_->segments.empty();
}

double PreparedMesh::signed_distance(const Vec3& v, Vec3* nearest, Vec3* face_normal,
                                     int* near_face) const {
  int side = 0;
  const double d = nearest_on_surface(v, nearest, face_normal, near_face, &side);
  if (!impl_->parity || d == 0) return -d;
  // The face's side is the solid's only when every face points outward.
  if (!impl_->oriented || side == 0)
    side = impl_->side(Point3(v.x(), v.y(), v.z())) == RaySide::kInside ? -1 : 1;
  return side < 0 ? d : -d;
}

double PreparedMesh::unsigned_distance(const Vec3& v, Vec3* nearest, Vec3* face_normal,
                                       int* near_face, int* side_of_face) const {
  return nearest_on_surface(v, nearest, face_normal, near_face, side_of_face);
}

double PreparedMesh::nearest_on_surface(const Vec3& v, Vec3* nearest, Vec3* face_normal,
                                        int* near_face, int* side) const {
  const Impl& m = *impl_;
  if (side) *side = 0;
  const Point3 p(v.x(), v.y(), v.z());
  Point3 q = p;
  double d2 = INFINITY;
  Vec3 normal = Vec3::Zero();
  if (m.faces > 0) {
    const TriangleTree::Nearest found = m.search.nearest(v, near_face ? *near_face : -1);
    if (near_face) *near_face = found.face;
    const Triangle3 face = m.face(found.face);
    q = Point3(found.point.x(), found.point.y(), found.point.z());
    d2 = CGAL::squared_distance(p, q);
    if (side) *side = face_side(m, v, q, found.face, d2);
    const K::Vector_3 n = CGAL::cross_product(face[1] - face[0], face[2] - face[0]);
    normal = Vec3(n.x(), n.y(), n.z()).normalized();
  }
  for (const Segment3& s : m.segments)
    if (CGAL::squared_distance(p, s) < d2) {
      q = m.closest(p);
      d2 = CGAL::squared_distance(p, q);
      if (side) *side = 0;
      normal.setZero();
      break;
    }
  if (face_normal) *face_normal = normal;
  if (nearest) *nearest = Vec3(q.x(), q.y(), q.z());
  return std::sqrt(d2);
}

void PreparedMesh::shell_sides(const Vec3& v, const std::vector<int>& face_shell, RaySide* sides,
                               size_t shells) const {
  const CGAL::Bbox_3& b = impl_->box;
  ray_parity_sides(impl_->search, face_shell, Vec3(b.xmin(), b.ymin(), b.zmin()),
                   Vec3(b.xmax(), b.ymax(), b.zmax()), v, sides, shells);
}

void PreparedMesh::faces_in_turned_box(const Eigen::Matrix3d& R, const Vec3& origin, const Vec3& lo,
                                       const Vec3& hi, std::vector<int>& out, size_t limit) const {
  impl_->search.in_turned_box(R, origin, lo, hi, out, limit);
}

std::array<Vec3, 3> PreparedMesh::face(int i) const {
  return impl_->search.triangle(i);
}

int PreparedMesh::faces() const {
  return impl_->faces;
}

Eigen::Matrix3d PreparedMesh::face_axes() const {
  return impl_->search.axes();
}

namespace {

using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int>;

// The boxes of a mesh's primitives in a frame (rows of F: its axes), each
// widened by `pad` for the rounding of taking corners there: primitive i is
// faces first, then segments.
std::vector<Box> primitive_boxes(const PreparedMesh::Impl& m, const Eigen::Matrix3d& F,
                                 double pad) {
  std::vector<Box> boxes;
  boxes.reserve(size_t(m.faces) + m.segments.size());
  const auto corner = [&](const Point3& p) { return Vec3(F * Vec3(p.x(), p.y(), p.z())); };
  const auto add = [&](Vec3 lo, Vec3 hi, std::size_t i) {
    lo.array() -= pad, hi.array() += pad;
    boxes.emplace_back(CGAL::Bbox_3(lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z()),
                       static_cast<int>(i));
  };
  for (int i = 0; i < m.faces; ++i) {
    const std::array<Vec3, 3>& t = m.search.triangle(i);
    const Vec3 a = F * t[0], b = F * t[1], c = F * t[2];
    add(a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c), i);
  }
  for (std::size_t i = 0; i < m.segments.size(); ++i) {
    const Vec3 a = corner(m.segments[i].source()), b = corner(m.segments[i].target());
    add(a.cwiseMin(b), a.cwiseMax(b), size_t(m.faces) + i);
  }
  return boxes;
}

// Only the boxes that meet `within` (where the two meshes' boxes overlap: a
// point two primitives share lies in both meshes' boxes). Boxes are closed,
// so touching boxes are kept.
void keep_within(std::vector<Box>& boxes, const CGAL::Bbox_3& within) {
  boxes.erase(std::remove_if(boxes.begin(), boxes.end(),
                             [&](const Box& b) { return !CGAL::do_overlap(b.bbox(), within); }),
              boxes.end());
}

CGAL::Bbox_3 box_of(const std::vector<Box>& boxes) {
  CGAL::Bbox_3 all;
  for (const Box& b : boxes) all += b.bbox();
  return all;
}

bool primitives_meet(const PreparedMesh::Impl& a, int i, const PreparedMesh::Impl& b, int j) {
  const int fa = a.faces, fb = b.faces;
  if (i < fa && j < fb) return CGAL::do_intersect(a.face(i), b.face(j));
  if (i < fa) return CGAL::do_intersect(a.face(i), b.segments[j - fb]);
  if (j < fb) return CGAL::do_intersect(b.face(j), a.segments[i - fa]);
  return CGAL::do_intersect(a.segments[i - fa], b.segments[j - fb]);
}

struct Found {};

// The primitives' boxes are taken in the face axes of the mesh with fewer
// faces (TriangleTree's, the world's when it is not turned): world boxes of a
// part placed askew are fat in every direction and met several times as
// many of the other part's. Only the pairing uses them; every pair is then
// tested exactly on the primitives as they are.
bool surfaces_meet(const PreparedMesh::Impl& a, const PreparedMesh::Impl& b) {
  // Faces only (no degenerate triangles kept as segments, which the trees do
  // not hold): the two trees walked together open only the subtrees that
  // meet, and a seated contact's first crossing faces are found after a few
  // hundred boxes instead of boxing every face of both.
  if (a.segments.empty() && b.segments.empty() && !a.search.empty() && !b.search.empty())
    return TriangleTree::pairs_near(
        a.search, b.search, [&](int i, int j) { return CGAL::do_intersect(a.face(i), b.face(j)); });
  const TriangleTree& small = a.faces <= b.faces ? a.search : b.search;
  const Eigen::Matrix3d F =
      small.rotated() ? Eigen::Matrix3d(small.axes().transpose()) : Eigen::Matrix3d::Identity();
  // Rounding of the corners taken into the frame (none in the world's).
  const auto reach_of = [](const CGAL::Bbox_3& x) {
    return std::max(Vec3(x.xmin(), x.ymin(), x.zmin()).cwiseAbs().maxCoeff(),
                    Vec3(x.xmax(), x.ymax(), x.zmax()).cwiseAbs().maxCoeff());
  };
  const double reach = std::max(reach_of(a.box), reach_of(b.box));
  const double pad = small.rotated() ? tol::kFrameRounding * reach : 0.0;
  std::vector<Box> ba = primitive_boxes(a, F, pad), bb = primitive_boxes(b, F, pad);
  const CGAL::Bbox_3 ea = box_of(ba), eb = box_of(bb);
  const CGAL::Bbox_3 both(std::max(ea.xmin(), eb.xmin()), std::max(ea.ymin(), eb.ymin()),
                          std::max(ea.zmin(), eb.zmin()), std::min(ea.xmax(), eb.xmax()),
                          std::min(ea.ymax(), eb.ymax()), std::min(ea.zmax(), eb.zmax()));
  keep_within(ba, both);
  keep_within(bb, both);
  try {
    CGAL::box_intersection_d(ba.begin(), ba.end(), bb.begin(), bb.end(),
                             [&](const Box& x, const Box& y) {
                               if (primitives_meet(a, x.info(), b, y.info())) throw Found{};
                             });
  } catch (const Found&) {
    return true;
  }
  return false;
}

// Some shell of `inner` has a vertex inside or on closed `outer`. Called when the
// surfaces do not meet, so each shell is wholly inside or wholly outside.
bool shell_inside(const PreparedMesh::Impl& inner, const PreparedMesh::Impl& outer) {
  if (!outer.parity) return false;
  for (int v : inner.shell_vertex)
    if (outer.side(inner.points[v]) != RaySide::kOutside) return true;
  return false;
}

// Deepest vertex of `inner` strictly inside closed `outer`.
void deepest_in(const PreparedMesh::Impl& inner, const PreparedMesh::Impl& outer, bool inner_is_a,
                MeshDepthBound& best) {
  if (!outer.parity) return;
  for (std::size_t col = 0; col < inner.merged.size(); ++col) {
    const int v = inner.merged[col];
    if (v < 0) continue;
    const Point3& p = inner.points[v];
    if (outer.side(p) != RaySide::kInside) continue;
    const Point3 q = outer.closest(p);
    const double d = std::sqrt(CGAL::squared_distance(p, q));
    if (!(d > best.depth)) continue;
    const Vec3 pv(p.x(), p.y(), p.z()), qv(q.x(), q.y(), q.z());
    best.depth = d;
    best.direction = (inner_is_a ? pv - qv : qv - pv) / d;
    best.vertex = static_cast<int>(col);
    best.vertex_of_a = inner_is_a;
    best.surface_point = qv;
  }
}

}  // namespace

bool meshes_intersect(const PreparedMesh& pa, const PreparedMesh& pb) {
  const PreparedMesh::Impl &a = pa.impl(), &b = pb.impl();
  if (!CGAL::do_overlap(a.box, b.box)) return false;
  if (surfaces_meet(a, b)) return true;
  return shell_inside(a, b) || shell_inside(b, a);
}

bool surfaces_meet(const PreparedMesh& a, const PreparedMesh& b) {
  return CGAL::do_overlap(a.impl().box, b.impl().box) && surfaces_meet(a.impl(), b.impl());
}

bool meshes_intersect(const Mesh& a, const Mesh& b) {
  return meshes_intersect(PreparedMesh(a), PreparedMesh(b));
}

MeshDepthBound deepest_vertex_depth(const PreparedMesh& pa, const PreparedMesh& pb) {
  const PreparedMesh::Impl &a = pa.impl(), &b = pb.impl();
  MeshDepthBound best;
  best.tested_in_a = a.parity;
  best.tested_in_b = b.parity;
  if (!CGAL::do_overlap(a.box, b.box)) return best;
  deepest_in(a, b, true, best);
  deepest_in(b, a, false, best);
  return best;
}

MeshDepthBound deepest_vertex_depth(const Mesh& a, const Mesh& b) {
  return deepest_vertex_depth(PreparedMesh(a), PreparedMesh(b));
}

}  // namespace pd
