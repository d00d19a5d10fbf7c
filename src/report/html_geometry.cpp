#include "report/html_geometry.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "geometry/cluster_vertices.h"
#include "geometry/convex_overlap.h"

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
  if (part.surface && part.surface->mesh && part.surface->mesh->triangles.cols() > 0) {
    const Mesh& mesh = *part.surface->mesh;
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
      m.how = "mesh, " + count_text(tris) + " triangles";
      return m;
    }
    // Halving the grid until it fits: at most 7 passes (256 down to 4 cells).
    for (int cells = 256; cells >= 4; cells /= 2) {
      const Mesh c = cluster_vertices(mesh, cells);
      if (static_cast<size_t>(c.triangles.cols()) > max_triangles) continue;
      listed(c);
      WebMesh m = make_web_mesh(c.vertices, list);
      m.how = "mesh of " + count_text(tris) + " triangles, vertices clustered on a " +
              std::to_string(cells) + "-cell grid to " + count_text(m.triangles.size());
      return m;
    }
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
