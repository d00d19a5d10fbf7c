// A nonconvex part for the HTML overlap tests: an L-shaped prism (two arms of
// width 4 along x and y from the origin, 60 and 40 long, z in [0, 10]) as a
// closed, outward-oriented triangle mesh, and the Part the refinement keeps
// for it (placed surface, nonconvex, its hull as its one piece).
#pragma once

#include <memory>

#include "geometry/hull.h"
#include "scene/parts.h"

namespace pd_test {

inline pd::Part l_prism_part(const std::string& id) {
  const double ring[6][2] = {{0, 0}, {60, 0}, {60, 4}, {4, 4}, {4, 40}, {0, 40}};
  auto mesh = std::make_shared<pd::Mesh>();
  mesh->vertices.resize(3, 12);
  for (int k = 0; k < 6; ++k) {
    mesh->vertices.col(k) = pd::Vec3(ring[k][0], ring[k][1], 0);
    mesh->vertices.col(k + 6) = pd::Vec3(ring[k][0], ring[k][1], 10);
  }
  std::vector<Eigen::Vector3i> tris;
  for (int k = 1; k + 1 < 6; ++k) {          // a fan from the corner (0, 0), which sees the whole L
    tris.emplace_back(0, k + 1, k);          // bottom, facing −z
    tris.emplace_back(6, 6 + k, 6 + k + 1);  // top, facing +z
  }
  for (int k = 0; k < 6; ++k) {  // the sides, counter-clockwise ring: outward
    const int n = (k + 1) % 6;
    tris.emplace_back(k, n, n + 6);
    tris.emplace_back(k, n + 6, k + 6);
  }
  mesh->triangles.resize(3, static_cast<long>(tris.size()));
  for (size_t t = 0; t < tris.size(); ++t) mesh->triangles.col(static_cast<long>(t)) = tris[t];
  pd::Part part;
  part.id = id;
  part.source = id + ".stl";
  part.pieces.push_back(pd::convex_hull(mesh->vertices));
  part.box = {pd::Vec3(0, 0, 0), pd::Vec3(60, 40, 10)};
  part.mode = pd::Pieces::kAuto;
  part.convex = false;
  part.surface.emplace();
  part.surface->file_mesh = mesh;
  part.surface->closed = true;
  return part;
}

}  // namespace pd_test
