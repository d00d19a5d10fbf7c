// Parts: a scene's part specs turned into convex pieces in scene units.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "geometry/aabb.h"
#include "geometry/hull.h"
#include "geometry/motion.h"
#include "scene/mesh_loader.h"
#include "scene/scene.h"

namespace pd {

struct Part {
  std::string id;
  std::string source;  ///< the mesh path, or "inline"
  long vertex_count = 0;
  std::vector<Hull> pieces;  ///< convex pieces (one unless pieces = "meshes")
  Aabb box;
  std::vector<std::string> warnings;
  std::optional<std::string> error;   ///< the part could not be used: its pairs are errors
  std::optional<RigidMotion> motion;  ///< moving parts only (checks.motion)

  long hull_vertex_count() const;
};

/// Loads, transforms and hulls every part. A part that fails gets `error` set
/// and the rest go on. A mesh file is read once (and reduced to its hull's
/// vertices once) whatever its instances' transforms; the same file under the
/// same units, transform and pieces is hulled once. `threads` > 1 hulls distinct parts in
/// parallel (the result does not depend on it); every thread has ended on return.
/// `on_built(n)`, when given, is called (from the building thread) as the geometry
/// of n scene parts is ready, for progress. Mesh files are read first, in up to
/// `threads` loader processes, each file within `load_timeout` seconds (0 = no
/// limit): a reader that hangs or crashes costs only its file's parts. Forks:
/// call it from a process with one thread.
std::vector<Part> build_parts(const SceneSpec& scene, int threads = 1,
                              const std::function<void(size_t)>& on_built = {},
                              double load_timeout = kDefaultLoadTimeout);

}  // namespace pd
