#include "report/html_geometry.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numeric>

#include "geometry/cluster_vertices.h"
#include "geometry/convex_overlap.h"
#include "geometry/solid_distance.h"
#include "tolerances.h"

namespace pd {

namespace {

std::string count_text(size_t n) {  // 12,000
  std::string s = std::to_string(n);
  for (int k = static_cast<int>(s.size()) - 3; k > 0; k -= 3) s.insert(static_cast<size_t>(k), ",");
  return s;
}

// Positions relative to the points' box centre; only the vertices the
// triangles use, renumbered.
WebMesh make_web_mesh(const Points& pts, const std::vector<std::array<int, 3>>& tris) {
  WebMesh m;
  if (tris.empty()) return m;
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (const auto& t : tris)
    for (int k : t) {
      lo = lo.cwiseMin(pts.col(k));
      hi = hi.cwiseMax(pts.col(k));
    }
  m.origin = (lo + hi) / 2;
  std::vector<long> index(static_cast<size_t>(pts.cols()), -1);
  for (const auto& t : tris) {
    std::array<unsigned, 3> out{};
    for (int c = 0; c < 3; ++c) {
      long& id = index[static_cast<size_t>(t[c])];
      if (id < 0) {
        id = static_cast<long>(m.vertex_count());
        const Vec3 p = pts.col(t[c]) - m.origin;
        for (int d = 0; d < 3; ++d) m.positions.push_back(static_cast<float>(p[d]));
      }
      out[c] = static_cast<unsigned>(id);
    }
    m.triangles.push_back(out);
  }
  return m;
}

// A flat convex polygon's points (any order) as a fan around their centroid,
// ordered by angle in the plane of their two main directions.
std::vector<std::array<int, 3>> polygon_fan(const Points& pts) {
  const Vec3 c = pts.rowwise().mean();
  const Eigen::Matrix3d cov = (pts.colwise() - c) * (pts.colwise() - c).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Vec3 u = eig.eigenvectors().col(2), v = eig.eigenvectors().col(1);
  std::vector<int> order(static_cast<size_t>(pts.cols()));
  std::iota(order.begin(), order.end(), 0);
  std::vector<double> angle(order.size());
  for (int k : order) {
    const Vec3 d = pts.col(k) - c;
    angle[static_cast<size_t>(k)] = std::atan2(d.dot(v), d.dot(u));
  }
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    return angle[static_cast<size_t>(i)] < angle[static_cast<size_t>(j)];
  });
  std::vector<std::array<int, 3>> tris;
  for (size_t k = 1; k + 1 < order.size(); ++k) tris.push_back({order[0], order[k], order[k + 1]});
  return tris;
}

// An even subsample of `n` of the columns (deterministic: every n/k-th).
Points subsample(const Points& pts, long n) {
  Points out(3, n);
  for (long k = 0; k < n; ++k) out.col(k) = pts.col(k * pts.cols() / n);
  return out;
}

std::vector<const Hull*> shown_pieces(const Part& part) {
  std::vector<const Hull*> out;
  const auto& pieces = part.decomposition ? part.decomposition->pieces : part.pieces;
  for (const Hull& h : pieces) out.push_back(&h);
  return out;
}

void append(WebMesh& to, const WebMesh& from) {
  // Both are re-based on `to.origin`, which is the first piece's.
  if (to.positions.empty()) {
    to = from;
    return;
  }
  const unsigned base = static_cast<unsigned>(to.vertex_count());
  const Vec3 shift = from.origin - to.origin;
  for (size_t k = 0; k < from.positions.size(); ++k)
    to.positions.push_back(static_cast<float>(from.positions[k] + shift[static_cast<long>(k % 3)]));
  for (const auto& t : from.triangles)
    to.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

// A mesh as at most `max_triangles`: as it is, else decimated by vertex
// clustering, halving the grid until it fits (at most 7 passes: 256 down to 4
// cells). Empty when even 4 cells are too many.
WebMesh mesh_within(const Mesh& mesh, size_t max_triangles, const std::string& what) {
  const size_t tris = static_cast<size_t>(mesh.triangles.cols());
  std::vector<std::array<int, 3>> list;
  auto listed = [&list](const Mesh& m) {
    list.clear();
    for (long k = 0; k < m.triangles.cols(); ++k)
      list.push_back({m.triangles(0, k), m.triangles(1, k), m.triangles(2, k)});
  };
  if (tris <= max_triangles) {
    listed(mesh);
    WebMesh m = make_web_mesh(mesh.vertices, list);
    m.how = what + ", " + count_text(tris) + " triangles";
    return m;
  }
  for (int cells = 256; cells >= 4; cells /= 2) {
    const Mesh c = cluster_vertices(mesh, cells);
    if (static_cast<size_t>(c.triangles.cols()) > max_triangles) continue;
    listed(c);
    WebMesh m = make_web_mesh(c.vertices, list);
    m.how = what + " of " + count_text(tris) + " triangles, vertices clustered on a " +
            std::to_string(cells) + "-cell grid to " + count_text(m.triangles.size());
    return m;
  }
  return {};
}

// The placed surface of a part the refinement decides on its surface (a
// nonconvex part, or any in pieces decompose), read back from the mesh
// store; none for any other part, or when the store has lost it (its hulls
// are drawn then).
std::optional<Mesh> shown_surface(const Part& part) {
  if (!part.surface || (part.convex == true && part.mode != Pieces::kDecompose))
    return std::nullopt;
  try {
    Mesh m = placed_mesh_of(*part.surface);
    if (m.triangles.cols() > 0) return m;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

// A part as the overlap sees it: its surface triangles and which points lie
// inside it. A nonconvex part (a placed surface mesh) by its SolidDistance; any
// other by its convex pieces (inside one of them).
class ShownSolid {
 public:
  explicit ShownSolid(const Part& part) {
    if (const std::optional<Mesh> surface = shown_surface(part); surface && part.convex != true) {
      const Mesh& mesh = *surface;
      try {
        solid_ = std::make_unique<SolidDistance>(mesh);
      } catch (const std::exception& e) {
        why_ = "part \"" + part.id + "\": " + e.what();
        return;
      }
      if (!solid_->closed()) {
        why_ = "part \"" + part.id + "\" is an open mesh (no inside to intersect)";
        return;
      }
      vertices_ = mesh.vertices;
      for (long k = 0; k < mesh.triangles.cols(); ++k)
        triangles_.push_back({mesh.triangles(0, k), mesh.triangles(1, k), mesh.triangles(2, k)});
      return;
    }
    long n = 0;
    std::vector<const Hull*> solid_pieces;
    for (const Hull* h : shown_pieces(part))
      if (h->dimension == 3) {
        HullFacets f;
        if (!hull_facets(h->vertices, f)) continue;
        const int base = static_cast<int>(n);
        for (const auto& t : f.triangles)
          triangles_.push_back({t[0] + base, t[1] + base, t[2] + base});
        n += h->vertices.cols();
        solid_pieces.push_back(h);
        facets_.push_back(std::move(f));
      }
    vertices_.resize(3, n);
    long at = 0;
    for (const Hull* h : solid_pieces) {
      vertices_.middleCols(at, h->vertices.cols()) = h->vertices;
      at += h->vertices.cols();
    }
    if (facets_.empty()) why_ = "part \"" + part.id + "\" has no solid piece";
  }

  const std::string& why_not() const { return why_; }
  const Points& vertices() const { return vertices_; }
  const std::vector<std::array<int, 3>>& triangles() const { return triangles_; }

  /// The coordinates' rounding (float32 steps of a mesh far from the origin).
  double noise() const { return solid_ ? solid_->noise() : 0.0; }

  /// Deeper than `margin` inside: a point on a face the two parts share (a
  /// seated contact) is outside, whichever way the rounding goes.
  bool inside(const Vec3& x, double margin) const {
    if (solid_) return solid_->at(x, nullptr, false).lower > margin;
    for (const HullFacets& f : facets_) {
      bool in = true;
      for (size_t k = 0; in && k < f.normals.size(); ++k)
        in = f.normals[k].dot(x) + f.offsets[k] < -margin;
      if (in) return true;
    }
    return false;
  }

 private:
  std::unique_ptr<SolidDistance> solid_;
  std::vector<HullFacets> facets_;
  Points vertices_ = Points(3, 0);
  std::vector<std::array<int, 3>> triangles_;
  std::string why_;
};

// The triangles of one surface inside the other solid, within `region` (a
// point outside it is outside the other part's box). Corners are classified
// by the other solid; a triangle whose corners all agree is kept or dropped
// whole once its longest edge is at most `coarse` (a part poking through a
// large face is caught at that scale), and one whose corners disagree is
// halved across its longest edge down to `fine` (CAD's long slivers are cut
// along their length only), its pieces kept by their centre's side. Counts
// inside tests in `probes`.
class OverlapSurface {
 public:
  OverlapSurface(const ShownSolid& from, const ShownSolid& other, const Aabb& region, double coarse,
                 double fine, double margin, long& probes)
      : other_(other),
        region_(region),
        coarse_(coarse),
        fine_(fine),
        margin_(margin),
        probes_(probes) {
    const Points& v = from.vertices();
    std::vector<signed char> side(static_cast<size_t>(v.cols()), -1);
    auto corner = [&](int k) {
      signed char& s = side[static_cast<size_t>(k)];
      if (s < 0) s = inside(v.col(k)) ? 1 : 0;
      return s == 1;
    };
    for (const auto& t : from.triangles()) {
      if (probes_ < 0) return;
      const Vec3 p = v.col(t[0]), q = v.col(t[1]), r = v.col(t[2]);
      if (!Aabb{p.cwiseMin(q).cwiseMin(r), p.cwiseMax(q).cwiseMax(r)}.overlaps(region_)) continue;
      add(p, q, r, corner(t[0]), corner(t[1]), corner(t[2]), 0);
    }
  }

  std::vector<Vec3> kept;  ///< three corners per triangle

 private:
  bool inside(const Vec3& x) {
    if ((x.array() < region_.lo.array()).any() || (x.array() > region_.hi.array()).any())
      return false;
    --probes_;
    return other_.inside(x, margin_);
  }

  void add(const Vec3& p, const Vec3& q, const Vec3& r, bool ip, bool iq, bool ir, int level) {
    if (probes_ < 0) return;
    if (!Aabb{p.cwiseMin(q).cwiseMin(r), p.cwiseMax(q).cwiseMax(r)}.overlaps(region_)) return;
    const bool same = ip == iq && iq == ir;
    const double longest = std::max({(p - q).norm(), (q - r).norm(), (r - p).norm()});
    if (level >= 24 || longest <= (same ? coarse_ : fine_)) {
      if (same ? ip : inside((p + q + r) / 3)) kept.insert(kept.end(), {p, q, r});
      return;
    }
    // Halved across the longest edge: (a, b) that edge, c the opposite corner.
    const double pq = (p - q).squaredNorm(), qr = (q - r).squaredNorm(), rp = (r - p).squaredNorm();
    if (pq >= qr && pq >= rp)
      halve(p, q, r, ip, iq, ir, level);
    else if (qr >= rp)
      halve(q, r, p, iq, ir, ip, level);
    else
      halve(r, p, q, ir, ip, iq, level);
  }

  // (a, m, c) and (m, b, c), m the middle of ab: the orientation of (a, b, c) kept.
  void halve(const Vec3& a, const Vec3& b, const Vec3& c, bool ia, bool ib, bool ic, int level) {
    const Vec3 m = (a + b) / 2;
    const bool im = inside(m);
    add(a, m, c, ia, im, ic, level + 1);
    add(m, b, c, im, ib, ic, level + 1);
  }

  const ShownSolid& other_;
  Aabb region_;
  double coarse_, fine_, margin_;
  long& probes_;
};

}  // namespace

WebMesh hull_web_mesh(const Points& vertices, size_t max_triangles) {
  if (vertices.cols() == 0) return {};
  const Hull hull = convex_hull(vertices);
  const long n = hull.vertices.cols();
  if (hull.dimension == 3) {
    // A hull of v vertices has at most 2v − 4 triangles.
    const long keep = std::max(4L, std::min(n, static_cast<long>(max_triangles / 2 + 2)));
    Points pts = keep < n ? subsample(hull.vertices, keep) : hull.vertices;
    HullFacets f;
    if (hull_facets(pts, f)) {
      WebMesh m = make_web_mesh(pts, f.triangles);
      m.how = keep < n ? "hull of " + count_text(static_cast<size_t>(keep)) + " of its " +
                             count_text(static_cast<size_t>(n)) + " hull vertices, " +
                             count_text(m.triangles.size()) + " triangles"
                       : "convex hull, " + count_text(m.triangles.size()) + " triangles";
      return m;
    }
  }
  if (hull.dimension >= 2) {
    const Points pts = n > static_cast<long>(max_triangles) + 2
                           ? subsample(hull.vertices, static_cast<long>(max_triangles) + 2)
                           : hull.vertices;
    WebMesh m = make_web_mesh(pts, polygon_fan(pts));
    m.how = "flat polygon, " + count_text(m.triangles.size()) + " triangles";
    return m;
  }
  return {};
}

Points part_vertices(const Part& part) {
  long n = 0;
  for (const Hull* h : shown_pieces(part)) n += h->vertices.cols();
  Points all(3, n);
  long at = 0;
  for (const Hull* h : shown_pieces(part)) {
    all.middleCols(at, h->vertices.cols()) = h->vertices;
    at += h->vertices.cols();
  }
  return all;
}

WebMesh part_web_mesh(const Part& part, size_t max_triangles) {
  if (part.error) return {};
  if (const std::optional<Mesh> surface = shown_surface(part)) {
    WebMesh m = mesh_within(*surface, max_triangles, "mesh");
    if (!m.triangles.empty()) return m;
  }
  const auto pieces = shown_pieces(part);
  if (pieces.empty()) return {};
  if (pieces.size() > 1) {
    WebMesh all;
    bool fits = true;
    for (const Hull* h : pieces) {
      append(all, hull_web_mesh(h->vertices, max_triangles));
      if (all.triangles.size() > max_triangles) {
        fits = false;
        break;
      }
    }
    if (fits) {
      all.how = count_text(pieces.size()) + " convex pieces, " + count_text(all.triangles.size()) +
                " triangles";
      return all;
    }
  }
  WebMesh m = hull_web_mesh(part_vertices(part), max_triangles);
  if (pieces.size() > 1)
    m.how += " (of " + count_text(pieces.size()) + " pieces: too many triangles)";
  return m;
}

size_t piece_count(const Part& part) {
  return shown_pieces(part).size();
}

const Hull* realising_piece(const Part& part, int index) {
  const auto pieces = shown_pieces(part);
  if (index < 0 || static_cast<size_t>(index) >= pieces.size()) return nullptr;
  return pieces[static_cast<size_t>(index)];
}

std::optional<WebMesh> overlap_web_mesh(const Points& a, const Points& b, size_t max_triangles) {
  const std::optional<Hull> overlap = convex_overlap(a, b);
  if (!overlap) return std::nullopt;
  WebMesh m = hull_web_mesh(overlap->vertices, max_triangles);
  if (m.triangles.empty()) return std::nullopt;
  return m;
}

SolidOverlap solid_overlap_web_mesh(const Part& a, const Part& b, size_t max_triangles) {
  SolidOverlap out;
  if (a.error || b.error) return out;
  const Aabb region{a.box.lo.cwiseMax(b.box.lo), a.box.hi.cwiseMin(b.box.hi)};
  if ((region.lo.array() > region.hi.array()).any()) return out;
  const ShownSolid sa(a), sb(b);
  for (const ShownSolid* s : {&sa, &sb})
    if (!s->why_not().empty()) {
      out.note = s->why_not();
      return out;
    }
  const double diagonal =
      std::max((region.hi - region.lo).norm(),
               1e-9 * std::max((a.box.hi - a.box.lo).norm(), (b.box.hi - b.box.lo).norm()));
  // Points within a few steps of the coordinates' rounding of a surface are on it.
  const double margin = 2 * std::max({a.resolution.value_or(0.0), b.resolution.value_or(0.0),
                                      sa.noise(), sb.noise(), 1e-12 * diagonal});
  long probes = tol::kHtmlOverlapProbes;
  const OverlapSurface in_b(sa, sb, region, diagonal / 8, diagonal / 48, margin, probes);
  const OverlapSurface in_a(sb, sa, region, diagonal / 8, diagonal / 48, margin, probes);
  if (probes < 0) {
    out.note = "more than " + count_text(static_cast<size_t>(tol::kHtmlOverlapProbes)) +
               " inside tests to draw";
    return out;
  }
  Mesh soup;
  const long n = static_cast<long>(in_b.kept.size() + in_a.kept.size());
  if (n == 0) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "no part of either surface lies deeper than the coordinates' rounding (%.3g) "
                  "inside the other",
                  margin);
    out.note = text;
    return out;
  }
  soup.vertices.resize(3, n);
  soup.triangles.resize(3, n / 3);
  long k = 0;
  for (const auto* kept : {&in_b.kept, &in_a.kept})
    for (const Vec3& v : *kept) {
      soup.vertices.col(k) = v;
      soup.triangles(k % 3, k / 3) = static_cast<int>(k);
      ++k;
    }
  WebMesh m = mesh_within(soup, max_triangles, "the faces of each part inside the other");
  if (m.triangles.empty()) {
    out.note = "more than " + count_text(max_triangles) + " triangles to draw";
    return out;
  }
  out.mesh = std::move(m);
  return out;
}

std::string base64(const void* data, size_t bytes) {
  static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* p = static_cast<const unsigned char*>(data);
  std::string out;
  out.reserve((bytes + 2) / 3 * 4);
  for (size_t k = 0; k < bytes; k += 3) {
    const unsigned v =
        (p[k] << 16) | (k + 1 < bytes ? p[k + 1] << 8 : 0) | (k + 2 < bytes ? p[k + 2] : 0);
    out += abc[(v >> 18) & 63];
    out += abc[(v >> 12) & 63];
    out += k + 1 < bytes ? abc[(v >> 6) & 63] : '=';
    out += k + 2 < bytes ? abc[v & 63] : '=';
  }
  return out;
}

}  // namespace pd
