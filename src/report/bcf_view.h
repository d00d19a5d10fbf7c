// Where a BCF viewpoint looks (--bcf): a perspective camera on a finding.
// docs/report-format.md, "BCF".
#pragma once

#include <optional>

#include "geometry/aabb.h"
#include "geometry/types.h"

namespace pd {

/// What the camera must show, in scene units: a ball around the target.
struct ViewTarget {
  Vec3 centre = Vec3::Zero();
  double radius = 1.0;
  bool at = false;  ///< the centre is the finding's `at`, not a box estimate
};

/// The ball of a pair with parts' boxes `a`, `b` (nullopt: the part has none):
/// centred on `at` when known, else on the centre of the boxes' overlap, or
/// midway between the boxes when they do not overlap; its radius half the
/// diagonal of the smaller box (the smaller part fills the view), at least half
/// the gap between the box centres when `at` is unknown; 1 scene unit when no
/// box is known.
ViewTarget view_target(const std::optional<Vec3>& at, const std::optional<Aabb>& a,
                       const std::optional<Aabb>& b);

struct PerspectiveCamera {
  Vec3 viewpoint, direction, up;  ///< direction and up: unit vectors, orthogonal
  double field_of_view = 0.0;     ///< vertical, degrees
  double aspect_ratio = 0.0;      ///< width / height
};

/// A camera whose vertical field of view (tol::kBcfFieldOfView) just holds the ball,
/// looking across `depth_direction` (so the depth shows as a length on screen,
/// as the HTML view does) from above: the isometric direction (1, 1, −1) with
/// its component along the depth removed; up is +z as far as the view allows
/// (BCF's world is z-up).
PerspectiveCamera camera_on(const ViewTarget& t, const Vec3& depth_direction);

}  // namespace pd
