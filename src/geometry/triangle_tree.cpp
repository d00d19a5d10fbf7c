#include "geometry/triangle_tree.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

#include "geometry/face_axes.h"
#include "tolerances.h"

namespace pd {

namespace {

// Plain three-component arithmetic for the routine every query runs on every
// triangle it visits: the sanitizer builds (-O1) leave Eigen's expression
// templates as calls, which made a query there several times slower.
struct P3 {
  double x, y, z;
};
inline P3 sub(const P3& a, const P3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline double dot(const P3& a, const P3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline P3 along(const P3& a, double t, const P3& d) {
  return {a.x + t * d.x, a.y + t * d.y, a.z + t * d.z};
}

P3 closest(const P3& p, const P3& a, const P3& b, const P3& c) {
  const P3 ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const P3 bp = sub(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return along(a, d1 / (d1 - d3), ab);
  const P3 cp = sub(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return along(a, d2 / (d2 - d6), ac);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return along(b, (d4 - d3) / ((d4 - d3) + (d5 - d6)), sub(c, b));
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {a.x + ab.x * v + ac.x * w, a.y + ab.y * v + ac.y * w, a.z + ab.z * v + ac.z * w};
}

inline P3 p3(const Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

}  // namespace

Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const P3 q = closest(p3(p), p3(a), p3(b), p3(c));
  return {q.x, q.y, q.z};
}

namespace {

// A leaf of a few triangles: fewer nodes to visit, and a triangle's test costs
// about as much as a box's.
constexpr int kLeafSize = 4;

// The deepest a path of the tree goes (the queries' stacks are sized by it).
constexpr int kMaxDepth = 64;

// Scalar loops rather than Eigen expressions: these run at every node of every
// query, and the sanitizer builds (-O1) do not flatten the expression templates.
// The box is widened by `pad` on every side.
double box_squared_distance(const Vec3& lo, const Vec3& hi, const Vec3& p, double pad) {
  double d2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double below = lo[k] - pad - p[k], above = p[k] - hi[k] - pad;
    const double d = below > 0 ? below : above > 0 ? above : 0.0;
    d2 += d * d;
  }
  return d2;
}

bool boxes_meet(const Vec3& lo, const Vec3& hi, const Vec3& a, const Vec3& b) {
  for (int k = 0; k < 3; ++k)
    if (a[k] > hi[k] || b[k] < lo[k]) return false;
  return true;
}

// Whether the segment a + t·d, t in [0, 1], may meet a box widened by `pad`
// on every side: the slab test, with the parameter interval padded so that
// rounding (of the reciprocals, taken once per segment) never drops a box the
// segment meets. An axis the segment does not move along compares its
// coordinate exactly (the axis-aligned rays of the inside tests).
class SegmentSlabs {
 public:
  SegmentSlabs(const Vec3& a, const Vec3& d, double pad) : a_(a), pad_(pad) {
    for (int k = 0; k < 3; ++k) inv_[k] = d[k] == 0 ? 0.0 : 1.0 / d[k];
  }
  bool meet(const Vec3& lo, const Vec3& hi) const {
    constexpr double kPad = 1e-9;  // in t: far above the reciprocal's rounding
    double t0 = -kPad, t1 = 1 + kPad;
    for (int k = 0; k < 3; ++k) {
      const double below = lo[k] - pad_ - a_[k], above = hi[k] + pad_ - a_[k];
      if (inv_[k] == 0) {
        if (below > 0 || above < 0) return false;
        continue;
      }
      const double enter = (inv_[k] > 0 ? below : above) * inv_[k],
                   leave = (inv_[k] > 0 ? above : below) * inv_[k];
      t0 = std::max(t0, enter - kPad);
      t1 = std::min(t1, leave + kPad);
      if (t0 > t1) return false;
    }
    return true;
  }

 private:
  Vec3 a_;
  Vec3 inv_;  ///< 1/d per axis, 0 where d is
  double pad_;
};

// Whether the axes are the world's, in some order and sense: then the boxes
// are the world's, so an unrotated part is searched exactly as before and
// its axis rays are met by comparisons.
bool worlds_axes(const Eigen::Matrix3d& axes) {
  return ((axes.cwiseAbs().array() > 1 - 1e-9).colwise().any()).all();
}

std::array<Vec3, 2> box_of(const std::array<Vec3, 3>& t) {
  return {t[0].cwiseMin(t[1]).cwiseMin(t[2]), t[0].cwiseMax(t[1]).cwiseMax(t[2])};
}

}  // namespace

TriangleTree::TriangleTree(const std::vector<std::array<Vec3, 3>>& triangles)
    : TriangleTree(triangles.data(), triangles.size()) {}

TriangleTree::TriangleTree(const std::array<Vec3, 3>* triangles, size_t count)
    : id_(count), slot_(count) {
  if (count == 0) return;
  std::iota(id_.begin(), id_.end(), 0);
  axes_ = face_axes(triangles, count);
  rotated_ = !worlds_axes(axes_);
  if (rotated_) frame_ = axes_.transpose();
  for (size_t i = 0; i < count; ++i)
    for (const Vec3& v : triangles[i]) extent_ = std::max(extent_, v.cwiseAbs().maxCoeff());
  // Each triangle taken into the frame on its own: no framed copy of them all.
  HugeVector<Vec3> centroids(count);
  HugeVector<std::array<Vec3, 2>> framed_boxes(count);
  for (size_t i = 0; i < count; ++i) {
    std::array<Vec3, 3> f = triangles[i];
    if (rotated_)
      for (Vec3& v : f) v = frame_ * v;
    centroids[i] = (f[0] + f[1] + f[2]) / 3;
    framed_boxes[i] = box_of(f);
  }
  // A node per split: fewer than the triangles (leaves hold one or more). Only
  // the pages written are backed, so the unused room costs no memory.
  nodes_.reserve(count);
  // Each triangle's bin at the split being made (a byte, where the partition
  // would otherwise take its centroid again from afar and divide).
  HugeVector<std::uint8_t> bin_of(count);
  root_ = build(0, static_cast<int>(count), framed_boxes, centroids, bin_of, 0);
  triangles_.resize(count);
  for (size_t i = 0; i < id_.size(); ++i) triangles_[i] = triangles[id_[i]];
  for (size_t i = 0; i < id_.size(); ++i) slot_[id_[i]] = static_cast<int>(i);
  boxes_.resize(count);
  for (size_t i = 0; i < count; ++i) boxes_[i] = framed_boxes[id_[i]];
}

// A point's frame coordinates are within a few roundings of its coordinates'
// size of the true ones (the frame is orthonormal to rounding), as are the
// boxes' corners: this bounds both, with room to spare.
double TriangleTree::pad(double reach) const {
  return rotated_ ? tol::kFrameRounding * (extent_ + reach) : 0.0;
}

// Depth first, the first child first; a subtree is entered when `meets`
// accepts its box, a leaf's triangle when it accepts the triangle's box. Stops
// when `visit` returns true, and says so. Each visit pushes at most two
// subtrees, one level down, and the build keeps the depth below kMaxDepth:
// the stack never holds more than twice that.
template <class Meets, class Visit>
bool TriangleTree::visit_boxes(const Meets& meets, const Visit& visit) const {
  if (triangles_.empty() || !meets(root_.lo, root_.hi)) return false;
  std::array<const Subtree*, 2 * kMaxDepth + 2> stack;
  int size = 0;
  stack[size++] = &root_;
  while (size > 0) {
    const Subtree& t = *stack[--size];
    if (t.count > 0) {
      for (int i = t.index; i < t.index + t.count; ++i)
        if (meets(boxes_[i][0], boxes_[i][1]) && visit(i)) return true;
      continue;
    }
    const Node& n = nodes_[t.index];
    if (meets(n.child[1].lo, n.child[1].hi)) stack[size++] = &n.child[1];
    if (meets(n.child[0].lo, n.child[0].hi)) stack[size++] = &n.child[0];
  }
  return false;
}

void TriangleTree::list_in_frame_box(const Vec3& lo, const Vec3& hi, std::vector<int>& out,
                                     size_t limit) const {
  const size_t before = out.size();
  const bool past_limit =
      visit_boxes([&](const Vec3& a, const Vec3& b) { return boxes_meet(lo, hi, a, b); },
                  [&](int slot) {
                    out.push_back(id_[slot]);
                    return out.size() - before > limit;
                  });
  if (!past_limit) std::sort(out.begin() + static_cast<std::ptrdiff_t>(before), out.end());
}

void TriangleTree::in_turned_box(const Eigen::Matrix3d& R, const Vec3& origin, const Vec3& lo,
                                 const Vec3& hi, std::vector<int>& out, size_t limit) const {
  // The turned box's box in the tree's frame: its centre taken there, its
  // half-extents spread by |frame·R|; widened by the rounding of both (the
  // centre's, from origin and R, even when the frame is the world's).
  const Vec3 c = to_frame(origin + R * (0.5 * (lo + hi)));
  const Vec3 e = (frame_ * R).cwiseAbs() * (0.5 * (hi - lo));
  const double w = tol::kFrameRounding * (extent_ + origin.cwiseAbs().maxCoeff() +
                                          lo.cwiseAbs().maxCoeff() + hi.cwiseAbs().maxCoeff());
  const Vec3 reach = e.array() + w;
  list_in_frame_box(c - reach, c + reach, out, limit);
}

bool TriangleTree::along_segment(const Vec3& a, const Vec3& b, const SegmentVisit& visit) const {
  const auto call = [&](int slot) { return visit(id_[slot], triangles_[slot]); };
  if (rotated_) {  // the segment in the frame, the boxes widened for its rounding
    const Vec3 fa = frame_ * a;
    const SegmentSlabs slabs(fa, frame_ * b - fa,
                             pad(std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff())));
    return visit_boxes([&](const Vec3& lo, const Vec3& hi) { return slabs.meet(lo, hi); }, call);
  }
  const Vec3 d = b - a;
  // Along an axis (the inside tests' rays), boxes are met by comparisons.
  const int moving = (d.x() != 0) + (d.y() != 0) + (d.z() != 0);
  if (moving == 1) {
    const int k = d.x() != 0 ? 0 : d.y() != 0 ? 1 : 2, u = (k + 1) % 3, v = (k + 2) % 3;
    const double from = std::min(a[k], b[k]), to = std::max(a[k], b[k]);
    return visit_boxes(
        [&](const Vec3& lo, const Vec3& hi) {
          return lo[u] <= a[u] && a[u] <= hi[u] && lo[v] <= a[v] && a[v] <= hi[v] && lo[k] <= to &&
                 from <= hi[k];
        },
        call);
  }
  const SegmentSlabs slabs(a, d, 0.0);
  return visit_boxes([&](const Vec3& lo, const Vec3& hi) { return slabs.meet(lo, hi); }, call);
}

namespace {

// Half the surface of a box: what a random query's chance of entering it
// grows with (the surface area heuristic).
double half_area(const Vec3& lo, const Vec3& hi) {
  const Vec3 d = (hi - lo).cwiseMax(0.0);
  return d.x() * d.y() + d.y() * d.z() + d.z() * d.x();
}

// How deep splits by the surface area heuristic go; below, median splits
// keep every path short: 24 levels here and 35 median ones hold 2^37
// triangles, within the queries' stacks (kMaxDepth).
constexpr int kSahDepth = 24;
constexpr int kSahBins = 12;

}  // namespace

// b's boxes are taken into a's frame as the boxes of their turned copies (M
// = a's frame times b's frame transposed: centre by M, half-extents by |M|),
// widened by the rounding of both frames and of M (as in_turned_box widens a
// turned box): a point of both triangles lies in a's box of its triangle and
// in the turned box of b's, so no pair that meets is passed over.
bool TriangleTree::pairs_near(const TriangleTree& a, const TriangleTree& b,
                              const PairVisit& visit) {
  if (a.triangles_.empty() || b.triangles_.empty()) return false;
  const Eigen::Matrix3d M = a.frame_ * b.frame_.transpose(), A = M.cwiseAbs();
  const double w = (a.rotated_ || b.rotated_)
                       ? 4 * tol::kFrameRounding * (a.extent_ + b.extent_)
                       : 0.0;  // both the world's: the boxes are compared as they are
  const auto turned = [&](const Vec3& lo, const Vec3& hi, Vec3& tlo, Vec3& thi) {
    const Vec3 c = M * (0.5 * (lo + hi)), e = (A * (0.5 * (hi - lo))).array() + w;
    tlo = c - e, thi = c + e;
  };
  // Pairs of subtrees whose boxes meet; the one with the larger box is opened
  // (a leaf only when the other is one too).
  struct Open {
    const Subtree *x, *y;
    Vec3 ylo, yhi;  ///< y's box in a's frame
  };
  std::vector<Open> stack;
  stack.reserve(4 * kMaxDepth);
  Open root{&a.root_, &b.root_, Vec3::Zero(), Vec3::Zero()};
  turned(b.root_.lo, b.root_.hi, root.ylo, root.yhi);
  if (!boxes_meet(a.root_.lo, a.root_.hi, root.ylo, root.yhi)) return false;
  stack.push_back(root);
  std::vector<std::array<Vec3, 2>> leaf_boxes;
  while (!stack.empty()) {
    const Open o = stack.back();
    stack.pop_back();
    const bool x_leaf = o.x->count > 0, y_leaf = o.y->count > 0;
    if (x_leaf && y_leaf) {
      leaf_boxes.resize(size_t(o.y->count));
      for (int j = 0; j < o.y->count; ++j)
        turned(b.boxes_[size_t(o.y->index + j)][0], b.boxes_[size_t(o.y->index + j)][1],
               leaf_boxes[size_t(j)][0], leaf_boxes[size_t(j)][1]);
      for (int i = o.x->index; i < o.x->index + o.x->count; ++i) {
        if (!boxes_meet(a.boxes_[size_t(i)][0], a.boxes_[size_t(i)][1], o.ylo, o.yhi)) continue;
        for (int j = 0; j < o.y->count; ++j)
          if (boxes_meet(a.boxes_[size_t(i)][0], a.boxes_[size_t(i)][1], leaf_boxes[size_t(j)][0],
                         leaf_boxes[size_t(j)][1]) &&
              visit(a.id_[size_t(i)], b.id_[size_t(o.y->index + j)]))
            return true;
      }
      continue;
    }
    const bool open_x =
        !x_leaf && (y_leaf || half_area(o.x->lo, o.x->hi) >= half_area(o.ylo, o.yhi));
    if (open_x) {
      const Node& n = a.nodes_[size_t(o.x->index)];
      for (int k = 1; k >= 0; --k)
        if (boxes_meet(n.child[k].lo, n.child[k].hi, o.ylo, o.yhi))
          stack.push_back({&n.child[k], o.y, o.ylo, o.yhi});
    } else {
      const Node& n = b.nodes_[size_t(o.y->index)];
      for (int k = 1; k >= 0; --k) {
        Open c{o.x, &n.child[k], Vec3::Zero(), Vec3::Zero()};
        turned(n.child[k].lo, n.child[k].hi, c.ylo, c.yhi);
        if (boxes_meet(o.x->lo, o.x->hi, c.ylo, c.yhi)) stack.push_back(c);
      }
    }
  }
  return false;
}

// The centroids split along their longest extent, in the frame: where the
// surface area heuristic (binned) finds a split, there, else at the median.
// CAD tessellations are full of long slivers whose boxes overlap; a median
// split cuts through a fan of them, while the heuristic keeps them apart
// from the compact triangles beside them.
TriangleTree::Subtree TriangleTree::build(int begin, int end,
                                          const HugeVector<std::array<Vec3, 2>>& boxes,
                                          const HugeVector<Vec3>& centroids,
                                          HugeVector<std::uint8_t>& bin_of, int depth) {
  Subtree s;
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  Vec3 clo = lo, chi = hi;
  for (int i = begin; i < end; ++i) {
    lo = lo.cwiseMin(boxes[id_[i]][0]), hi = hi.cwiseMax(boxes[id_[i]][1]);
    clo = clo.cwiseMin(centroids[id_[i]]), chi = chi.cwiseMax(centroids[id_[i]]);
  }
  s.lo = lo;
  s.hi = hi;
  if (end - begin <= kLeafSize) {
    s.index = begin;
    s.count = end - begin;
    return s;
  }
  int axis = 0;
  const double extent = (chi - clo).maxCoeff(&axis);
  int mid = -1;
  if (depth < kSahDepth && extent > 0) {
    const auto bin = [&](int t) {
      return std::min(kSahBins - 1,
                      static_cast<int>((centroids[t][axis] - clo[axis]) / extent * kSahBins));
    };
    std::array<int, kSahBins> count{};
    std::array<Vec3, kSahBins> blo, bhi;
    blo.fill(Vec3::Constant(INFINITY));
    bhi.fill(Vec3::Constant(-INFINITY));
    for (int i = begin; i < end; ++i) {
      const int t = id_[i], b = bin(t);
      bin_of[size_t(t)] = static_cast<std::uint8_t>(b);  // for the partition below
      ++count[b];
      blo[b] = blo[b].cwiseMin(boxes[t][0]), bhi[b] = bhi[b].cwiseMax(boxes[t][1]);
    }
    // The right side's area and count after each bin, then the best cut.
    std::array<double, kSahBins> right_area{};
    std::array<int, kSahBins> right_count{};
    Vec3 rlo = Vec3::Constant(INFINITY), rhi = Vec3::Constant(-INFINITY);
    int n = 0;
    for (int b = kSahBins - 1; b > 0; --b) {
      rlo = rlo.cwiseMin(blo[b]), rhi = rhi.cwiseMax(bhi[b]), n += count[b];
      right_area[b] = half_area(rlo, rhi), right_count[b] = n;
    }
    Vec3 llo = Vec3::Constant(INFINITY), lhi = Vec3::Constant(-INFINITY);
    double best = INFINITY;
    int cut = -1, left = 0;
    for (int b = 0; b + 1 < kSahBins; ++b) {
      llo = llo.cwiseMin(blo[b]), lhi = lhi.cwiseMax(bhi[b]), left += count[b];
      if (left == 0 || right_count[b + 1] == 0) continue;
      const double cost = half_area(llo, lhi) * left + right_area[b + 1] * right_count[b + 1];
      if (cost < best) best = cost, cut = b;
    }
    if (cut >= 0)
      mid = static_cast<int>(std::partition(id_.begin() + begin, id_.begin() + end,
                                            [&](int t) { return bin_of[size_t(t)] <= cut; }) -
                             id_.begin());
  }
  if (mid <= begin || mid >= end) {
    mid = begin + (end - begin) / 2;
    std::nth_element(id_.begin() + begin, id_.begin() + mid, id_.begin() + end,
                     [&](int x, int y) { return centroids[x][axis] < centroids[y][axis]; });
  }
  s.index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  const Subtree first = build(begin, mid, boxes, centroids, bin_of, depth + 1),
                second = build(mid, end, boxes, centroids, bin_of, depth + 1);
  nodes_[s.index].child[0] = first;
  nodes_[s.index].child[1] = second;
  return s;
}

TriangleTree::Nearest TriangleTree::nearest(const Vec3& p, int start) const {
  Nearest best;
  if (triangles_.empty()) return best;
  const P3 query = p3(p);
  const Vec3 f = to_frame(p);  // for the boxes
  const double w = pad(p.cwiseAbs().maxCoeff());
  const auto test = [&](int slot) {
    const auto& t = triangles_[slot];
    const P3 q = closest(query, p3(t[0]), p3(t[1]), p3(t[2]));
    const P3 d = sub(q, query);
    const double d2 = dot(d, d);
    if (d2 < best.squared_distance) best = {Vec3(q.x, q.y, q.z), id_[slot], d2};
  };
  if (start >= 0 && start < static_cast<int>(slot_.size())) test(slot_[start]);
  // Depth first, the nearer child first; a subtree no nearer than the best is
  // skipped. A subtree's box distance is computed once, when its parent is
  // visited, and kept beside it on the stack (as in visit_boxes, sized by kMaxDepth).
  struct Open {
    const Subtree* tree;
    double d2;
  };
  std::array<Open, 2 * kMaxDepth + 2> stack;
  int size = 0;
  stack[size++] = {&root_, box_squared_distance(root_.lo, root_.hi, f, w)};
  while (size > 0) {
    const Open open = stack[--size];
    if (!(open.d2 < best.squared_distance)) continue;
    const Subtree& t = *open.tree;
    if (t.count > 0) {
      for (int i = t.index; i < t.index + t.count; ++i) test(i);
      continue;
    }
    const Subtree &left = nodes_[t.index].child[0], &right = nodes_[t.index].child[1];
    const double dl = box_squared_distance(left.lo, left.hi, f, w),
                 dr = box_squared_distance(right.lo, right.hi, f, w);
    // Pushed last is searched first.
    if (dl < dr) {
      if (dr < best.squared_distance) stack[size++] = {&right, dr};
      if (dl < best.squared_distance) stack[size++] = {&left, dl};
    } else {
      if (dl < best.squared_distance) stack[size++] = {&left, dl};
      if (dr < best.squared_distance) stack[size++] = {&right, dr};
    }
  }
  return best;
}

}  // namespace pd
