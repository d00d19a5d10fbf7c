// Bullet's HACD (Debian's libbullet-extras-dev) on the parts of
// pdbench_decompose, for the choice of decomposer in docs/solver.md: pieces,
// wall time, and the largest concavity of a piece's hull against the part as
// pdcheck estimates it (hull_concavity, the measure decompose_convex bounds),
// for a sweep of HACD's concavity parameter. Built only when HACD is installed.
#include <HACD/hacdHACD.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "corpus/cad_shapes.h"
#include "geometry/convexity.h"
#include "geometry/decompose.h"
#include "geometry/mesh_intersect.h"

using namespace pd;
using namespace pd::shapes;

namespace {

struct Result {
  size_t pieces = 0;
  double seconds = 0.0, worst = 0.0;
};

// The largest concavity of a piece's hull against the part (full estimate).
double worst_piece(const std::vector<Points>& pieces, const PreparedMesh& part, double tol) {
  double worst = 0.0;
  for (const Points& p : pieces) {
    if (p.cols() < 4) continue;
    worst = std::max(worst, hull_concavity(p, part, tol, -1.0, Points(3, 0)).value);
  }
  return worst;
}

Result run_hacd(const Mesh& m, double concavity, const PreparedMesh& part, double tol) {
  std::vector<HACD::Vec3<HACD::Real>> points(m.vertices.cols());
  for (long i = 0; i < m.vertices.cols(); ++i)
    points[i] = HACD::Vec3<HACD::Real>(m.vertices(0, i), m.vertices(1, i), m.vertices(2, i));
  std::vector<HACD::Vec3<long>> tris(m.triangles.cols());
  for (long t = 0; t < m.triangles.cols(); ++t)
    tris[t] = HACD::Vec3<long>(m.triangles(0, t), m.triangles(1, t), m.triangles(2, t));
  const auto t0 = std::chrono::steady_clock::now();
  HACD::HACD h;
  h.SetPoints(points.data());
  h.SetNPoints(points.size());
  h.SetTriangles(tris.data());
  h.SetNTriangles(tris.size());
  h.SetNClusters(1);           // as few as the concavity allows
  h.SetNVerticesPerCH(10000);  // no hull decimation: it would move the hulls off the part
  h.SetConcavity(concavity);
  h.SetAddExtraDistPoints(true);
  h.SetAddFacesPoints(true);
  h.SetAddNeighboursDistPoints(false);
  h.Compute();
  std::vector<Points> pieces;
  for (size_t c = 0; c < h.GetNClusters(); ++c) {
    std::vector<HACD::Vec3<HACD::Real>> p(h.GetNPointsCH(c));
    std::vector<HACD::Vec3<long>> t(h.GetNTrianglesCH(c));
    h.GetCH(c, p.data(), t.data());
    Points q(3, static_cast<long>(p.size()));
    for (size_t i = 0; i < p.size(); ++i) q.col(i) = Vec3(p[i].X(), p[i].Y(), p[i].Z());
    pieces.push_back(q);
  }
  Result r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.pieces = pieces.size();
  r.worst = worst_piece(pieces, part, tol);
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const double tol = argc > 1 ? std::atof(argv[1]) : 0.025;  // concavity tolerance, mm
  const Vec3 far(20000.0, -3000.0, 500.0);
  struct Case {
    std::string name;
    Mesh mesh;
  };
  const std::vector<Case> cases = {
      {"plate 40x40x6, hole r5, 16 segments", plate_with_hole(40, 6, 5, 16)},
      {"plate 40x40x6, hole r5, 96 segments", plate_with_hole(40, 6, 5, 96)},
      {"L-bracket 40x40x20, t5", l_bracket(40, 5, 20)},
      {"hollow housing 30x20x10, wall 1.5", hollow_box({0, 0, 0}, {30, 20, 10}, 1.5)},
      {"board 3x2 holes r1, 16 segments", drilled_board(3, 2, 10, 1.6, 1, 16)}};
  std::printf(
      "| part | method | pieces | worst piece concavity (mm) | pieces within %.3g mm | seconds |\n",
      tol);
  std::printf("|---|---|---|---|---|---|\n");
  for (const Case& c : cases) {
    // Centred (HACD works in single coordinates; pdcheck centres before any arithmetic too).
    Mesh m = float32(translated(c.mesh, far));
    m.vertices.colwise() -= m.vertices.rowwise().mean();
    const PreparedMesh part(m);
    const auto t0 = std::chrono::steady_clock::now();
    const Decomposition d = decompose_convex(m, tol, 30.0);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double w = worst_piece(d.pieces, part, tol);
    std::printf("| %s | pdcheck | %zu | %.4f | %s | %.3f |\n", c.name.c_str(), d.pieces.size(), w,
                w <= tol ? "all" : "no", s);
    // HACD scales the mesh into [0, 1000] before it measures concavity: its
    // parameter is k · tol in those units.
    const double extent =
        (m.vertices.rowwise().maxCoeff() - m.vertices.rowwise().minCoeff()).maxCoeff();
    for (double k : {0.1, 1.0, 10.0}) {
      const Result r = run_hacd(m, k * tol * 1000.0 / extent, part, tol);
      std::printf("| %s | HACD, concavity %.3g mm | %zu | %.4f | %s | %.3f |\n", c.name.c_str(),
                  k * tol, r.pieces, r.worst, r.worst <= tol ? "all" : "no", r.seconds);
      std::fflush(stdout);
    }
  }
}
