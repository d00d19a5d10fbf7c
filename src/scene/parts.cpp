#include "scene/parts.h"

#include <algorithm>
#include <map>
#include <new>
#include <sstream>

#include "parallel_for.h"
#include "scene/mesh_loader.h"

namespace pd {

long Part::hull_vertex_count() const {
  long n = 0;
  for (const auto& h : pieces) n += h.vertices.cols();
  return n;
}

namespace {

Points place(const Points& p, const PartSpec& spec) {
  // Units first (the mesh's own unit to the scene's), then the part transform.
  const Points scaled = p * spec.to_scene_units;
  return (spec.transform.topLeftCorner<3, 3>() * scaled).colwise() +
         Vec3(spec.transform.topRightCorner<3, 1>());
}

std::string cache_key(const PartSpec& s) {
  std::ostringstream k;
  k.precision(17);
  k << *s.mesh << '|' << s.to_scene_units << '|' << int(s.pieces);
  for (int i = 0; i < 16; ++i) k << '|' << s.transform(i / 4, i % 4);
  return k.str();
}

Part build_part(const PartSpec& spec) {
  Part part;
  part.id = spec.id;
  part.source = spec.mesh ? *spec.mesh : "inline";
  try {
    std::vector<Points> sets;
    if (spec.mesh)
      sets = load_mesh_vertices(*spec.mesh, spec.pieces == Pieces::kMeshes);
    else
      sets.push_back(*spec.vertices);
    bool first = true;
    for (size_t k = 0; k < sets.size(); ++k) {
      part.vertex_count += sets[k].cols();
      Hull h = convex_hull(place(sets[k], spec));
      for (auto& w : h.warnings)
        part.warnings.push_back(sets.size() > 1 ? "piece " + std::to_string(k) + ": " + w : w);
      const Aabb b = Aabb::of(h.vertices);
      part.box = first ? b : part.box.merged(b);
      first = false;
      part.pieces.push_back(std::move(h));
    }
  } catch (const MeshError& e) {
    part.pieces.clear();
    part.error = e.what();  // names the file already
  } catch (const std::exception& e) {
    part.pieces.clear();
    part.error =
        (spec.mesh ? "mesh file " + *spec.mesh + ": " : std::string()) +
        (dynamic_cast<const std::bad_alloc*>(&e) ? "out of memory while loading (corrupt file?)"
                                                 : e.what());
  }
  return part;
}

}  // namespace

std::vector<Part> build_parts(const SceneSpec& scene, int threads,
                              const std::function<void(size_t)>& on_built) {
  // Distinct geometry first: the same mesh file under the same units,
  // transform and pieces is loaded and hulled once. Inline parts are distinct.
  std::vector<const PartSpec*> unique;
  std::vector<size_t> users;  // scene parts per distinct geometry
  std::vector<size_t> source(scene.parts.size());
  std::map<std::string, size_t> seen;
  for (size_t k = 0; k < scene.parts.size(); ++k) {
    const PartSpec& spec = scene.parts[k];
    if (spec.mesh) {
      const auto [it, fresh] = seen.emplace(cache_key(spec), unique.size());
      source[k] = it->second;
      if (!fresh) {
        ++users[it->second];
        continue;
      }
    } else {
      source[k] = unique.size();
    }
    unique.push_back(&spec);
    users.push_back(1);
  }

  // Hulls are independent: qhull_r keeps its state per run, each assimp
  // Importer its own, and build_part catches whatever it throws.
  std::vector<Part> built(unique.size());
  parallel_for(unique.size(), threads, [&](size_t u) {
    built[u] = build_part(*unique[u]);
    if (on_built) on_built(users[u]);
  });

  std::vector<Part> parts;
  parts.reserve(scene.parts.size());
  for (size_t k = 0; k < scene.parts.size(); ++k) {
    Part p = built[source[k]];
    p.id = scene.parts[k].id;
    p.motion = scene.parts[k].motion;
    parts.push_back(std::move(p));
  }
  return parts;
}

}  // namespace pd
