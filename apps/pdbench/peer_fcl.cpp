// FCL 0.7 (Debian libfcl-dev): signed distance between two fcl::Convex, which
// runs libccd's GJK and, when they overlap, its EPA (the default solver,
// GST_LIBCCD, and the default tolerances: what a developer gets).
#include <fcl/geometry/shape/convex.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>

#include <chrono>
#include <cmath>
#include <exception>
#include <memory>

#include "geometry/hull.h"
#include "peers.h"

namespace pdbench {

namespace {

// The hull of the points as an fcl::Convex (qhull's triangles as its faces).
std::shared_ptr<fcl::Convexd> convex(const pd::Points& x) {
  pd::HullFacets f;
  const pd::Points v = pd::convex_hull(x).vertices;
  auto verts = std::make_shared<std::vector<fcl::Vector3d>>();
  for (Eigen::Index k = 0; k < v.cols(); ++k) verts->emplace_back(v.col(k));
  auto faces = std::make_shared<std::vector<int>>();
  int count = 0;
  if (pd::hull_facets(v, f)) {
    for (const auto& t : f.triangles) {
      faces->insert(faces->end(), {3, t[0], t[1], t[2]});
      ++count;
    }
  }
  return std::make_shared<fcl::Convexd>(verts, count, faces);
}

}  // namespace

PeerRun fcl_signed_distance(const pd::Points& a, const pd::Points& b) {
  PeerRun r;
  try {
    fcl::CollisionObjectd oa(convex(a)), ob(convex(b));
    fcl::DistanceRequestd req;
    req.enable_signed_distance = true;
    req.enable_nearest_points = true;
    fcl::DistanceResultd res;
    const auto t0 = std::chrono::steady_clock::now();
    fcl::distance(&oa, &ob, req, res);
    r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (!std::isfinite(res.min_distance)) r.failure = "non-finite distance";
    r.depth = res.min_distance < 0 ? -res.min_distance : 0.0;
  } catch (const std::exception& e) {
    r.failure = e.what();
  }
  return r;
}

}  // namespace pdbench
