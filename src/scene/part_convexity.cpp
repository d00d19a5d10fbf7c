#include "scene/part_convexity.h"

#include <algorithm>
#include <cmath>

#include "geometry/convexity.h"
#include "geometry/hull.h"
#include "geometry/same_position.h"
#include "scene/mesh_store.h"

namespace pd {

namespace {

// File units, at this part's stretch: voids count at its tolerance, and the
// estimate stops once it is nonconvex for it (or beyond the noise).
double tolerance_of(const PartSurface& s) {
  return s.concavity_tol / s.stretch;
}
double stop_above_of(const PartSurface& s) {
  return std::max(tolerance_of(s), s.noise);
}

// The file's hull and its facets as the loader's qhull run found them (kept
// beside the surface in the mesh store), else found again the same way (a
// hull from the hull cache comes without facets): the same measure either way.
std::pair<Points, HullTriangles> file_hull_of(const PartSurface& s, const Mesh& m) {
  if (s.stored && s.stored->store)
    if (auto kept = s.stored->store->get_hull(s.stored->key)) return std::move(*kept);
  HullTriangles facets;
  Points vertices =
      convex_hull(distinct_positions(m.vertices, first_at_same_position(m.vertices)), &facets)
          .vertices;
  return {std::move(vertices), std::move(facets)};
}

}  // namespace

bool convexity_unmeasured(const Part& p) {
  return p.convexity_on_demand() && !p.convex && !p.error;
}

std::string convexity_key_of(const Part& p) {
  const PartSurface& s = *p.surface;
  return convexity_key(s.file_hash, tolerance_of(s), stop_above_of(s));
}

StoredConvexity measure_file_convexity(
    const Part& p, const std::string& cache_dir,
    const std::function<std::shared_ptr<const PreparedMesh>(const Mesh&)>& prepared) {
  const PartSurface& s = *p.surface;
  const std::string key = convexity_key_of(p);
  if (auto hit = read_cached_convexity(cache_dir, key)) return *hit;
  const std::shared_ptr<const Mesh> mesh = file_mesh_of(s);
  // The file's own hull (the same whichever instance asks), as the loader
  // found it: no second qhull run of the file.
  const auto [hull_points, hull_facets] = file_hull_of(s, *mesh);
  const HullTriangles* facets = hull_facets.triangles.empty() ? nullptr : &hull_facets;
  const std::shared_ptr<const PreparedMesh> held = prepared ? prepared(*mesh) : nullptr;
  const ConvexityScreen screen =
      held ? screen_convexity(*mesh, *held, tolerance_of(s), stop_above_of(s), &hull_points, facets)
           : screen_convexity(*mesh, tolerance_of(s), stop_above_of(s), &hull_points, facets);
  const StoredConvexity c{screen.concavity.value, screen.closed};
  write_cached_convexity(cache_dir, key, c);
  return c;
}

bool convex_by(const Part& p, const StoredConvexity& c) {
  return c.concavity <= stop_above_of(*p.surface);
}

void set_convexity(Part& p, const StoredConvexity& c) {
  PartSurface& s = *p.surface;
  p.convex = convex_by(p, c);
  s.concavity = c.concavity * s.stretch;
  s.closed = c.closed;
}

void measure_convexity(Part& p, const std::string& cache_dir) {
  set_convexity(p, measure_file_convexity(p, cache_dir));
}

}  // namespace pd
