#include "geometry/aabb.h"

namespace pd {

Aabb Aabb::of(const Points& pts) {
  return {pts.rowwise().minCoeff(), pts.rowwise().maxCoeff()};
}

}  // namespace pd
