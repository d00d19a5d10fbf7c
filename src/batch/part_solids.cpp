#include "batch/part_solids.h"

#include <malloc.h>

#include <algorithm>

#include "geometry/hull.h"
#include "tolerances.h"

namespace pd {

size_t solid_bytes(long triangles) {
  // Measured as the resident growth of building them on closed CAD meshes of
  // 10^4–10^6 triangles (scripts/bench_scale.py's parts), rounded up.
  return size_t(std::max(0L, triangles)) * tol::kSolidBytesPerTriangle + (64u << 10);
}

bool placed_as_file(const Part& p) {
  return p.surface && p.surface->placement == Mat4::Identity();
}

std::shared_ptr<const Mesh> surface_mesh(const Part& p) {
  if (placed_as_file(p)) return file_mesh_of(*p.surface);
  if (p.surface) return std::make_shared<const Mesh>(placed_mesh_of(*p.surface));
  auto m = std::make_shared<Mesh>();
  std::vector<Vec3> v;
  std::vector<std::array<int, 3>> t;
  for (const Hull& h : p.pieces) {
    HullFacets f;
    if (!hull_facets(h.vertices, f)) continue;
    const int base = static_cast<int>(v.size());
    for (Eigen::Index k = 0; k < h.vertices.cols(); ++k) v.push_back(h.vertices.col(k));
    for (size_t k = 0; k < f.triangles.size(); ++k) {  // outward, as the normal says
      auto tri = f.triangles[k];
      const Vec3 n = (h.vertices.col(tri[1]) - h.vertices.col(tri[0]))
                         .cross(h.vertices.col(tri[2]) - h.vertices.col(tri[0]));
      if (n.dot(f.normals[k]) < 0) std::swap(tri[1], tri[2]);
      t.push_back({base + tri[0], base + tri[1], base + tri[2]});
    }
  }
  m->vertices.resize(3, v.size());
  for (size_t k = 0; k < v.size(); ++k) m->vertices.col(k) = v[k];
  m->triangles.resize(3, t.size());
  for (size_t k = 0; k < t.size(); ++k)
    m->triangles.col(k) = Eigen::Vector3i(t[k][0], t[k][1], t[k][2]);
  return m;
}

std::shared_ptr<const SolidDistance> PartSolids::of(int p) {
  return cache_.get(p, [&] {
    auto d = std::make_shared<const SolidDistance>(*surface_mesh(parts_[size_t(p)]));
    return ByteCache<int, SolidDistance>::Built{d, solid_bytes(d->mesh().faces())};
  });
}

std::shared_ptr<const SolidDistance> PartSolids::of(int p, const Mesh& file_mesh) {
  if (!placed_as_file(parts_[size_t(p)])) return of(p);
  return cache_.get(p, [&] {
    auto d = std::make_shared<const SolidDistance>(file_mesh);
    return ByteCache<int, SolidDistance>::Built{d, solid_bytes(d->mesh().faces())};
  });
}

void PartSolids::let_go(int p) {
  cache_.erase(p);
  malloc_trim(0);
}

void PartSolids::give_back_dropped() {
  // The distances' freed huge-page blocks stay kept (128 MB at most,
  // geometry/huge_page_allocator.h): the next build takes them without
  // faulting fresh pages, which giving them back here made every build do
  // again once the budget was full (the 4M scene's refinement: 9.0-9.4 s ->
  // 7.2-7.8 s).
  if (const size_t dropped = cache_.drops(); dropped > given_back_.exchange(dropped))
    malloc_trim(0);
}

}  // namespace pd
