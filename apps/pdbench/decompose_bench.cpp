// Measures decompose_convex on CAD-like parts stored as float32 at x ≈ 20,000 mm
// (docs/solver.md, "Nonconvex parts"): pieces, completeness, estimated concavity
// and wall time per part, one markdown row each.
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "corpus/cad_shapes.h"
#include "geometry/decompose.h"

using namespace pd;
using namespace pd::shapes;

int main(int argc, char** argv) {
  const double tol = argc > 1 ? std::atof(argv[1]) : 0.025;   // concavity tolerance, mm
  const double limit = argc > 2 ? std::atof(argv[2]) : 30.0;  // time box, s
  const std::string only = argc > 3 ? argv[3] : "";           // rows whose name contains it
  const Vec3 far(20000.0, -3000.0, 500.0);
  struct Case {
    std::string name;
    Mesh mesh;
  };
  std::vector<Case> cases;
  for (int n : {16, 32, 64, 96, 128})
    cases.push_back({"plate 40x40x6, hole r5, " + std::to_string(n) + " segments",
                     plate_with_hole(40, 6, 5, n)});
  cases.push_back({"L-bracket 40x40x20, t5", l_bracket(40, 5, 20)});
  cases.push_back({"hollow housing 30x20x10, wall 1.5", hollow_box({0, 0, 0}, {30, 20, 10}, 1.5)});
  cases.push_back({"board 3x2 holes r1, 16 segments", drilled_board(3, 2, 10, 1.6, 1, 16)});
  std::printf("| part | triangles | pieces | complete | concavity (mm) | estimates | seconds |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (Case& c : cases) {
    if (c.name.find(only) == std::string::npos) continue;
    const Mesh m = float32(translated(c.mesh, far));
    const auto t0 = std::chrono::steady_clock::now();
    const Decomposition d = decompose_convex(m, tol, limit);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("| %s | %ld | %zu | %s | %.4f | %ld | %.3f |\n", c.name.c_str(),
                static_cast<long>(m.triangles.cols()), d.pieces.size(),
                d.complete ? "yes" : ("no: " + d.note).c_str(), d.concavity, d.work, s);
    std::fflush(stdout);
  }
}
