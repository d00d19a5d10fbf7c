#include "solve/epa.h"

#include <algorithm>
#include <array>
#include <functional>
#include <vector>

#include "solve/gjk.h"
#include "tolerances.h"

namespace pd {

bool DepthBracket::certified() const {
  return upper - lower <= tol::kEpaBracket;
}

namespace {

// A face of the polytope: vertices counter-clockwise seen from outside; edge k
// runs from v[k] to v[k+1] and is shared with face adj[k] (its edge adj_edge[k]).
struct Face {
  std::array<int, 3> v;
  std::array<int, 3> adj{-1, -1, -1};
  std::array<int, 3> adj_edge{-1, -1, -1};
  Vec3 n;      // unit outward normal (rounded: the bound below does not trust it)
  double low;  // min over the three vertices of n·x: the face's distance bound
  bool alive = true;
  int pass = -1;  // the expansion that removed or reached it
};

class Polytope {
 public:
  std::vector<Vec3> x;
  std::vector<MinkowskiIndex> id;  // each vertex's p_i − q_j, for the exact step
  std::vector<Face> faces;
  // The faces by bound, nearest on top; a removed face leaves when it reaches
  // the top. Deep pairs with a ring of near-tied minima (a shaft through a
  // ring's hull) take thousands of expansions: a scan per expansion was most
  // of their time.
  std::vector<std::pair<double, int>> by_low;
  // Scratch of one expansion, kept across expansions (allocations were a tenth
  // of a 30+30 pair's time under perf).
  std::vector<int> removed, from, to;
  std::vector<std::pair<int, int>> horizon;

  Polytope() {
    x.reserve(64);
    id.reserve(64);
    faces.reserve(128);
  }

  // A face through vertices (a, b, c) in that order; false when the triangle is
  // degenerate (no normal). The origin need not be inside it: the bound holds
  // only while every face has it inside by more than the rounding (epa_bracket).
  bool add_face(int a, int b, int c) {
    Face f;
    f.v = {a, b, c};
    const Vec3 n = (x[b] - x[a]).cross(x[c] - x[a]);
    const double len = n.norm();
    if (!(len > 0)) return false;
    f.n = n / len;
    f.low = std::min({f.n.dot(x[a]), f.n.dot(x[b]), f.n.dot(x[c])});
    by_low.emplace_back(f.low, static_cast<int>(faces.size()));
    std::push_heap(by_low.begin(), by_low.end(), std::greater<>());
    faces.push_back(f);
    return true;
  }

  // The live face of least bound (the lowest index among equal bounds).
  int nearest() {
    while (!by_low.empty() && !faces[by_low.front().second].alive) {
      std::pop_heap(by_low.begin(), by_low.end(), std::greater<>());
      by_low.pop_back();
    }
    return by_low.empty() ? -1 : by_low.front().second;
  }

  // The removed region seen from w: faces whose plane has w beyond it by more
  // than the rounding, connected to `start`; the horizon is the edges from a
  // removed face to a kept one, as (kept face, its edge).
  bool visible(const Face& f, const Vec3& w) const {
    return f.n.dot(w) > f.low + tol::kEpaRounding;
  }
  void silhouette(int f, int e, const Vec3& w, int pass) {
    Face& g = faces[f];
    if (g.pass == pass) {
      if (!g.alive || std::find(removed.begin(), removed.end(), f) != removed.end()) return;
    }
    if (g.pass != pass && visible(g, w)) {
      g.pass = pass;
      removed.push_back(f);
      for (int k = 1; k <= 2; ++k) {
        const int ek = (e + k) % 3;
        silhouette(g.adj[ek], g.adj_edge[ek], w, pass);
      }
      return;
    }
    g.pass = pass;
    horizon.emplace_back(f, e);
  }

  // Replaces the faces visible from w (starting at face `start`) by the cone from
  // w over their boundary: the surface stays closed and consistently oriented.
  // False when the step cannot (the boundary is not a simple cycle, or a new
  // face is degenerate): the polytope may then be partly rebuilt and is not
  // used again.
  bool expand(int start, const Vec3& w, const MinkowskiIndex& wid, int pass) {
    removed.assign(1, start);
    horizon.clear();
    faces[start].pass = pass;
    for (int e = 0; e < 3; ++e) silhouette(faces[start].adj[e], faces[start].adj_edge[e], w, pass);
    // The horizon must be one simple cycle: each vertex starts one edge and ends one.
    const size_t h = horizon.size();
    if (h < 3) return false;
    from.resize(h);
    to.resize(h);
    for (size_t i = 0; i < h; ++i) {
      const Face& g = faces[horizon[i].first];
      from[i] = g.v[horizon[i].second];
      to[i] = g.v[(horizon[i].second + 1) % 3];
    }
    for (size_t i = 0; i < h; ++i)
      for (size_t j = i + 1; j < h; ++j)
        if (from[i] == from[j] || to[i] == to[j]) return false;
    for (int f : removed) faces[f].alive = false;
    const int wi = static_cast<int>(x.size());
    x.push_back(w);
    id.push_back(wid);
    const int first = static_cast<int>(faces.size());
    for (size_t i = 0; i < h; ++i) {
      // The kept face's edge (from → to) is (to → from) in the new face.
      if (!add_face(to[i], from[i], wi)) return false;
      Face& nf = faces.back();
      Face& g = faces[horizon[i].first];
      nf.adj[0] = horizon[i].first;
      nf.adj_edge[0] = horizon[i].second;
      g.adj[horizon[i].second] = first + static_cast<int>(i);
      g.adj_edge[horizon[i].second] = 0;
    }
    // New face i: edge 1 (from_i → w) meets the new face j with edge 2 (w → to_j),
    // to_j = from_i.
    for (size_t i = 0; i < h; ++i) {
      size_t j = 0;
      while (j < h && to[j] != from[i]) ++j;
      if (j == h) return false;
      Face &fi = faces[first + i], &fj = faces[first + j];
      fi.adj[1] = first + static_cast<int>(j);
      fi.adj_edge[1] = 2;
      fj.adj[2] = first + static_cast<int>(i);
      fj.adj_edge[2] = 1;
    }
    return true;
  }
};

// The four faces of GJK's tetrahedron, outward. The origin may lie on a face or
// an edge of it (symmetric pairs): the expansion lifts such faces first, since
// they are the nearest. False when the tetrahedron is flat.
bool start_polytope(Polytope& poly, const std::array<Vec3, 4>& t,
                    const std::array<MinkowskiIndex, 4>& ids) {
  poly.x.assign(t.begin(), t.end());
  poly.id.assign(ids.begin(), ids.end());
  const double volume = (t[1] - t[0]).cross(t[2] - t[0]).dot(t[3] - t[0]);
  if (volume == 0) return false;
  if (volume > 0) {
    std::swap(poly.x[1], poly.x[2]);
    std::swap(poly.id[1], poly.id[2]);
  }
  // Now vertex 3 lies below face (0, 1, 2): every face below is outward.
  static constexpr int kFaces[4][3] = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
  for (const auto& f : kFaces)
    if (!poly.add_face(f[0], f[1], f[2])) return false;
  // Adjacency: the face holding each edge reversed.
  for (int f = 0; f < 4; ++f)
    for (int e = 0; e < 3; ++e) {
      const int a = poly.faces[f].v[e], b = poly.faces[f].v[(e + 1) % 3];
      for (int g = 0; g < 4; ++g)
        for (int k = 0; k < 3; ++k)
          if (poly.faces[g].v[k] == b && poly.faces[g].v[(k + 1) % 3] == a) {
            poly.faces[f].adj[e] = g;
            poly.faces[f].adj_edge[e] = k;
          }
    }
  return true;
}

// A closed bracket at a depth where its width is a sizeable fraction of it:
// the faces an exact recomputation must look at (solve/exact_facet.h), those
// whose bound is within 4·kEpaRounding of the nearest one's. Every other face
// is farther than the nearest by more than the rounding of the unit frame and
// of its bound (each below kEpaRounding), exactly too.
void keep_near_faces(const Polytope& poly, const Face& nearest, DepthBracket& b) {
  if (!(b.upper < tol::kExactFacetDepth)) return;
  b.nearest_low = nearest.low;
  for (const Face& f : poly.faces) {
    if (!f.alive || f.low > nearest.low + 4 * tol::kEpaRounding) continue;
    if (b.near_faces.size() == kMaxNearFaces) {
      b.near_faces.clear();  // too many near-tied faces: no exact step
      return;
    }
    b.near_faces.push_back({poly.id[f.v[0]], poly.id[f.v[1]], poly.id[f.v[2]]});
  }
  b.vertices = poly.id;
}

}  // namespace

DepthBracket epa_bracket(const PairProblem& pr, int max_iterations) {
  DepthBracket b;
  const GjkResult g = gjk_enclose_origin(pr, tol::kGjkMaxIterations);
  b.upper = g.gap;
  b.direction = g.direction;
  b.lower = g.lower;
  if (g.outcome == GjkResult::Outcome::kSeparated) {
    b.separated = true;
    return b;
  }
  if (g.outcome != GjkResult::Outcome::kEnclosed) return b;
  Polytope poly;
  if (!start_polytope(poly, g.tetrahedron, g.tetrahedron_ids)) return b;
  for (int it = 0; it < max_iterations; ++it) {
    const int f = poly.nearest();
    const Face face = poly.faces[f];
    // When every face has the origin inside by more than the rounding (the
    // nearest one has), the closed surface winds around it: the ball up to the
    // surface lies in D, and the nearest face's bound, lowered by the
    // rounding, bounds the depth. Before that (the origin on a face of GJK's
    // tetrahedron) the expansion lifts the nearest face and no bound is taken.
    if (face.low > tol::kEpaRounding) b.lower = std::max(b.lower, face.low - tol::kEpaRounding);
    Vec3 w;
    MinkowskiIndex wid;
    const double h = pr.support(face.n, w, wid);
    if (h < b.upper) {
      b.upper = h;
      b.direction = face.n;
    }
    if (b.certified()) {
      keep_near_faces(poly, face, b);
      return b;
    }
    // w must lie beyond the nearest face for the polytope to grow towards D's
    // boundary; otherwise the face is a facet up to a normal too rounded to
    // close the bracket (or, before the origin is enclosed, the pair touches
    // on that face's plane), and MLSL takes over from here.
    if (!poly.visible(face, w)) return b;
    b.iterations = it + 1;
    if (!poly.expand(f, w, wid, it)) return b;
  }
  return b;
}

}  // namespace pd
