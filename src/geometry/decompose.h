// Approximate convex decomposition of a closed mesh: convex pieces whose hulls
// cover the part and stay within a concavity tolerance of it (the paper's §V:
// the depth of a nonconvex pair is the largest depth over piece pairs).
#pragma once

#include <string>
#include <vector>

#include "geometry/mesh.h"
#include "geometry/types.h"
#include "tolerances.h"

namespace pd {

struct Decomposition {
  /// Vertex sets in the mesh's coordinates; each piece is the hull of its set.
  /// Together the hulls cover the part (every point of the solid, or of the
  /// surface of an open mesh, lies in some piece's hull).
  std::vector<Points> pieces;
  /// Every piece's hull is within the tolerance of the part (estimated: see
  /// hull_concavity in geometry/convexity.h). False when the time box, the
  /// piece limit or an open mesh stopped the decomposition: the pieces still
  /// cover the part but some hull may fill a concavity (the caller treats the
  /// pair's depth from them as unconfirmed).
  bool complete = false;
  std::string note;        ///< why not complete, or what was done
  double seconds = 0.0;    ///< wall time spent
  double concavity = 0.0;  ///< largest estimated piece concavity (scene units)
  long work = 0;           ///< concavity estimates spent (DecomposeLimits::work)
};

/// When a decomposition gives up. The work budget counts concavity estimates
/// (the unit of cost: one per cell and per tried merge), so a run within it is
/// reproducible on any machine (tests set it); the wall-clock box is a safety
/// net for users. Past either, the pieces so far are returned, complete = false.
struct DecomposeLimits {
  double seconds = tol::kDecomposeSeconds;
  long work = tol::kDecomposeMaxWork;
};

/// Cuts the closed mesh m with planes through its deepest concavities until
/// every piece's hull is within concavity_tol (scene units) of m, then merges
/// neighbouring pieces while their joint hull stays within it. A convex mesh
/// (within the tolerance) is one piece; separate shells, none inside another,
/// are decomposed one by one. Open meshes are not cut: one piece per shell,
/// complete = false. Stops at time_limit_seconds (wall clock) with what it has.
/// Memory stays proportional to the mesh times the piece limit
/// (tol::kDecomposeMaxPieces). Coordinates are centred before any arithmetic.
Decomposition decompose_convex(const Mesh& m, double concavity_tol, const DecomposeLimits& limits);
/// The same with the default work budget and the given time box.
Decomposition decompose_convex(const Mesh& m, double concavity_tol, double time_limit_seconds);

}  // namespace pd
