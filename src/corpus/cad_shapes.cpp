#include "corpus/cad_shapes.h"

#include <array>
#include <cmath>
#include <stdexcept>

namespace pd::shapes {

namespace {

// Triangles are collected as index triples, then packed into a Mesh.
struct Builder {
  std::vector<Vec3> v;
  std::vector<std::array<int, 3>> t;
  int add(const Vec3& p) {
    v.push_back(p);
    return static_cast<int>(v.size()) - 1;
  }
  void tri(int a, int b, int c) { t.push_back({a, b, c}); }
  void quad(int a, int b, int c, int d) {  // counter-clockwise a, b, c, d
    tri(a, b, c);
    tri(a, c, d);
  }
  Mesh mesh() const {
    Mesh m;
    m.vertices.resize(3, static_cast<long>(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i) m.vertices.col(i) = v[i];
    m.triangles.resize(3, static_cast<long>(t.size()));
    for (std::size_t i = 0; i < t.size(); ++i)
      m.triangles.col(i) = Eigen::Vector3i(t[i][0], t[i][1], t[i][2]);
    return m;
  }
};

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Ear clipping of a simple counter-clockwise polygon: triangles as index triples.
std::vector<std::array<int, 3>> ear_clip(const std::vector<Vec2>& p) {
  std::vector<int> left(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) left[i] = static_cast<int>(i);
  std::vector<std::array<int, 3>> out;
  while (left.size() > 3) {
    bool clipped = false;
    const std::size_t n = left.size();
    for (std::size_t k = 0; k < n && !clipped; ++k) {
      const int a = left[(k + n - 1) % n], b = left[k], c = left[(k + 1) % n];
      if (cross(p[b] - p[a], p[c] - p[b]) <= 0) continue;  // reflex or flat
      bool empty = true;
      for (int q : left) {
        if (q == a || q == b || q == c) continue;
        if (cross(p[b] - p[a], p[q] - p[a]) >= 0 && cross(p[c] - p[b], p[q] - p[b]) >= 0 &&
            cross(p[a] - p[c], p[q] - p[c]) >= 0)
          empty = false;
      }
      if (!empty) continue;
      out.push_back({a, b, c});
      left.erase(left.begin() + static_cast<long>(k));
      clipped = true;
    }
    if (!clipped)
      throw std::invalid_argument("ear_clip: polygon is not simple and counter-clockwise");
  }
  out.push_back({left[0], left[1], left[2]});
  return out;
}

// Rings `outer` and `inner` (same count, matched by index, both counter-clockwise)
// give an annular prism from z0 to z1.
Mesh ring_prism(const std::vector<Vec2>& outer, const std::vector<Vec2>& inner, double z0,
                double z1) {
  Builder b;
  const int n = static_cast<int>(outer.size());
  std::vector<int> ob(n), ot(n), ib(n), it(n);
  for (int i = 0; i < n; ++i) {
    ob[i] = b.add({outer[i].x(), outer[i].y(), z0});
    ot[i] = b.add({outer[i].x(), outer[i].y(), z1});
    ib[i] = b.add({inner[i].x(), inner[i].y(), z0});
    it[i] = b.add({inner[i].x(), inner[i].y(), z1});
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    b.quad(ot[i], ot[j], it[j], it[i]);  // top, seen from +z
    b.quad(ob[j], ob[i], ib[i], ib[j]);  // bottom
    b.quad(ob[i], ob[j], ot[j], ot[i]);  // outer wall
    b.quad(ib[j], ib[i], it[i], it[j]);  // hole wall, facing the axis
  }
  return b.mesh();
}

}  // namespace

Mesh box(const Vec3& lo, const Vec3& hi) {
  return prism({{lo.x(), lo.y()}, {hi.x(), lo.y()}, {hi.x(), hi.y()}, {lo.x(), hi.y()}}, lo.z(),
               hi.z());
}

Mesh prism(const std::vector<Vec2>& polygon, double z0, double z1) {
  Builder b;
  const int n = static_cast<int>(polygon.size());
  for (const Vec2& p : polygon) b.add({p.x(), p.y(), z0});
  for (const Vec2& p : polygon) b.add({p.x(), p.y(), z1});
  for (const auto& e : ear_clip(polygon)) {
    b.tri(n + e[0], n + e[1], n + e[2]);
    b.tri(e[2], e[1], e[0]);
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    b.quad(i, j, n + j, n + i);
  }
  return b.mesh();
}

std::vector<Vec2> circle(const Vec2& centre, double radius, int segments, double phase) {
  std::vector<Vec2> c(segments);
  for (int i = 0; i < segments; ++i) {
    const double a = phase + 2.0 * M_PI * i / segments;
    c[i] = centre + radius * Vec2(std::cos(a), std::sin(a));
  }
  return c;
}

Mesh cylinder(const Vec2& centre, double radius, double z0, double z1, int segments) {
  return prism(circle(centre, radius, segments), z0, z1);
}

Mesh stepped_shaft(double shank_radius, double head_radius, double z0, double z1, double z2,
                   int segments) {
  // Rings: shank bottom, shank top, head bottom (same z), head top; and the
  // two cap centres. Every quad between consecutive rings runs
  // counter-clockwise seen from outside.
  const int n = segments;
  const std::vector<std::pair<double, double>> rings{
      {shank_radius, z0}, {shank_radius, z1}, {head_radius, z1}, {head_radius, z2}};
  Mesh m;
  m.vertices.resize(3, 4 * n + 2);
  for (int r = 0; r < 4; ++r)
    for (int i = 0; i < n; ++i) {
      const double a = 2.0 * M_PI * i / n;
      m.vertices.col(r * n + i) =
          Vec3(rings[r].first * std::cos(a), rings[r].first * std::sin(a), rings[r].second);
    }
  const int bottom = 4 * n, top = 4 * n + 1;
  m.vertices.col(bottom) = Vec3(0, 0, z0);
  m.vertices.col(top) = Vec3(0, 0, z2);
  std::vector<Eigen::Vector3i> tris;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    tris.push_back({bottom, j, i});
    tris.push_back({top, 3 * n + i, 3 * n + j});
    // Shank side and head side run upwards (outward normal); the shoulder's
    // annulus (rings 1 to 2) faces down.
    for (int r : {0, 2}) {
      tris.push_back({r * n + i, r * n + j, (r + 1) * n + j});
      tris.push_back({r * n + i, (r + 1) * n + j, (r + 1) * n + i});
    }
    tris.push_back({n + i, n + j, 2 * n + j});
    tris.push_back({n + i, 2 * n + j, 2 * n + i});
  }
  m.triangles.resize(3, static_cast<long>(tris.size()));
  for (size_t t = 0; t < tris.size(); ++t) m.triangles.col(static_cast<long>(t)) = tris[t];
  return m;
}

namespace {

// The square [-h, h]² sampled where the rays at angles 2πi/n meet it (n a
// multiple of 8, so the corners are samples). Built from one table of tangents
// by symmetry, so neighbouring squares share their edge samples bit for bit.
std::vector<Vec2> square_outline(const Vec2& c, double h, int n) {
  if (n % 8 != 0) throw std::invalid_argument("square outline: segments % 8 != 0");
  auto tan_k = [&](int k) {  // tan(2πk/n) for |k| <= n/8, odd in k, ±1 at the ends
    const int a = std::abs(k);
    const double t = 8 * a == n ? 1.0 : std::tan(2.0 * M_PI * a / n);
    return k < 0 ? -t : t;
  };
  std::vector<Vec2> out(n);
  for (int i = 0; i < n; ++i) {
    const int e = n / 8;
    if (i <= e || i >= n - e)
      out[i] = c + Vec2(h, h * tan_k(i <= e ? i : i - n));  // right edge
    else if (i <= 3 * e)
      out[i] = c + Vec2(h * tan_k(n / 4 - i), h);  // top
    else if (i <= 5 * e)
      out[i] = c + Vec2(-h, h * tan_k(n / 2 - i));  // left
    else
      out[i] = c + Vec2(h * tan_k(i - 3 * n / 4), -h);  // bottom
  }
  return out;
}

}  // namespace

Mesh plate_with_hole(double side, double thickness, double hole_radius, int segments) {
  return ring_prism(square_outline({0, 0}, side / 2, segments),
                    circle({0, 0}, hole_radius, segments), 0.0, thickness);
}

Mesh drilled_board(int nx, int ny, double pitch, double thickness, double hole_radius,
                   int segments) {
  Builder b;
  const double h = pitch / 2;
  const int n = segments;
  for (int cx = 0; cx < nx; ++cx)
    for (int cy = 0; cy < ny; ++cy) {
      const Vec2 c(pitch * cx + h, pitch * cy + h);
      const std::vector<Vec2> outer = square_outline(c, h, n), inner = circle(c, hole_radius, n);
      std::vector<int> ob(n), ot(n), ib(n), it(n);
      for (int i = 0; i < n; ++i) {
        ob[i] = b.add({outer[i].x(), outer[i].y(), 0.0});
        ot[i] = b.add({outer[i].x(), outer[i].y(), thickness});
        ib[i] = b.add({inner[i].x(), inner[i].y(), 0.0});
        it[i] = b.add({inner[i].x(), inner[i].y(), thickness});
      }
      for (int i = 0; i < n; ++i) {
        const int j = (i + 1) % n;
        b.quad(ot[i], ot[j], it[j], it[i]);
        b.quad(ob[j], ob[i], ib[i], ib[j]);
        b.quad(ib[j], ib[i], it[i], it[j]);
        // Outer walls only on the board's boundary: inside, cells share edges.
        const Vec2 mid = 0.5 * (outer[i] + outer[j]);
        const bool boundary =
            mid.x() == 0.0 || mid.y() == 0.0 || mid.x() == pitch * nx || mid.y() == pitch * ny;
        if (boundary) b.quad(ob[i], ob[j], ot[j], ot[i]);
      }
    }
  return b.mesh();
}

Mesh l_bracket(double a, double t, double width) {
  return prism({{0, 0}, {a, 0}, {a, t}, {t, t}, {t, a}, {0, a}}, 0.0, width);
}

Mesh hollow_box(const Vec3& lo, const Vec3& hi, double wall) {
  const Vec3 w = Vec3::Constant(wall);
  return joined({box(lo, hi), flipped(box(lo + w, hi - w))});
}

Mesh revolution(const std::vector<Vec2>& profile, int segments) {
  const int n = static_cast<int>(profile.size());
  std::vector<std::vector<int>> ring(n);  // per profile point: its vertices
  std::vector<Vec3> v;
  for (int i = 0; i < n; ++i) {
    const Vec2& p = profile[i];
    if (p.x() <= 0) {
      ring[i].assign(segments, static_cast<int>(v.size()));
      v.emplace_back(0.0, 0.0, p.y());
      continue;
    }
    for (int k = 0; k < segments; ++k) {
      ring[i].push_back(static_cast<int>(v.size()));
      const double a = 2 * M_PI * k / segments;
      v.emplace_back(p.x() * std::cos(a), p.x() * std::sin(a), p.y());
    }
  }
  std::vector<std::array<int, 3>> t;
  for (int i = 0; i < n; ++i) {
    const std::vector<int>&a = ring[i], &b = ring[(i + 1) % n];
    for (int k = 0; k < segments; ++k) {
      const int k1 = (k + 1) % segments;
      // Profile edge a → b counter-clockwise in (ρ, z): its outward side faces
      // right of the direction of travel; the quad a_k, b_k, b_k1, a_k1.
      if (a[k] != a[k1]) t.push_back({a[k], a[k1], b[k]});
      if (b[k] != b[k1]) t.push_back({a[k1], b[k1], b[k]});
    }
  }
  Mesh m;
  m.vertices.resize(3, static_cast<long>(v.size()));
  for (size_t i = 0; i < v.size(); ++i) m.vertices.col(static_cast<long>(i)) = v[i];
  m.triangles.resize(3, static_cast<long>(t.size()));
  for (size_t i = 0; i < t.size(); ++i)
    for (int k = 0; k < 3; ++k) m.triangles(k, static_cast<long>(i)) = t[i][k];
  return m;
}

Mesh translated(Mesh m, const Vec3& offset) {
  m.vertices.colwise() += offset;
  return m;
}

Mesh float32(Mesh m) {
  for (long i = 0; i < m.vertices.size(); ++i)
    m.vertices.data()[i] = static_cast<double>(static_cast<float>(m.vertices.data()[i]));
  return m;
}

Mesh joined(const std::vector<Mesh>& parts) {
  long nv = 0, nt = 0;
  for (const Mesh& p : parts) nv += p.vertices.cols(), nt += p.triangles.cols();
  Mesh m;
  m.vertices.resize(3, nv);
  m.triangles.resize(3, nt);
  long v = 0, t = 0;
  for (const Mesh& p : parts) {
    m.vertices.middleCols(v, p.vertices.cols()) = p.vertices;
    m.triangles.middleCols(t, p.triangles.cols()) = p.triangles.array() + static_cast<int>(v);
    v += p.vertices.cols();
    t += p.triangles.cols();
  }
  return m;
}

Mesh flipped(Mesh m) {
  m.triangles.row(1).swap(m.triangles.row(2));
  return m;
}

}  // namespace pd::shapes
