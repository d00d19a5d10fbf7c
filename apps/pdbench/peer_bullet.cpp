// Bullet 3.24 (Debian libbullet-dev, built with single-precision btScalar):
// btGjkEpaSolver2::SignedDistance between two btConvexHullShape with margin 0.
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>
#include <btBulletCollisionCommon.h>

#include <chrono>
#include <cmath>

#include "geometry/hull.h"
#include "peers.h"

namespace pdbench {

namespace {

void fill(btConvexHullShape& s, const pd::Points& x) {
  const pd::Points v = pd::convex_hull(x).vertices;
  for (Eigen::Index k = 0; k < v.cols(); ++k)
    s.addPoint(btVector3(btScalar(v(0, k)), btScalar(v(1, k)), btScalar(v(2, k))), false);
  s.recalcLocalAabb();
  s.setMargin(0);
}

}  // namespace

PeerRun bullet_gjk_epa(const pd::Points& a, const pd::Points& b) {
  PeerRun r;
  btConvexHullShape sa, sb;
  fill(sa, a);
  fill(sb, b);
  btTransform id;
  id.setIdentity();
  btGjkEpaSolver2::sResults res;
  const auto t0 = std::chrono::steady_clock::now();
  btGjkEpaSolver2::SignedDistance(&sa, id, &sb, id, btVector3(1, 0, 0), res);
  r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (res.status == btGjkEpaSolver2::sResults::EPA_Failed) r.failure = "EPA failed";
  if (!std::isfinite(double(res.distance))) r.failure = "non-finite distance";
  r.depth = res.distance < 0 ? -double(res.distance) : 0.0;
  return r;
}

}  // namespace pdbench
