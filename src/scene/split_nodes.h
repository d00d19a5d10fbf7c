// `"split": "nodes"`: a multi-mesh file as one part per node
// (docs/scene-format.md "Split by node").
#pragma once

#include <functional>

#include "scene/mesh_loader.h"
#include "scene/scene.h"

namespace pd {

/// How split_node_parts reads the split parts' files (scene/mesh_loader.h).
struct SplitLoad {
  int threads = 1;
  double timeout = kDefaultLoadTimeout;
  double memory_mb = kAutoLoadMemory;
  MeshLoadHook before_load;  ///< tests only
  /// Where node paths are cached per file content (node_names_cache.h); "" = none.
  std::string cache_dir;
  /// A B-rep file read whole keeps its meshes for the parts stage when they
  /// take at most this (MB; the run's --memory budget), else its names alone.
  double keep_mb = 256.0;
  /// Progress: called with the number of files to read before reading them,
  /// then once per file read (a STEP file is read and meshed here: minutes
  /// for a large assembly).
  std::function<void(size_t files)> on_files;
  std::function<void()> on_read;
};

/// Replaces every `"split": "nodes"` part by one part per node of its mesh file
/// that holds meshes (a B-rep file without `"split"`, split_auto, only when it
/// holds more than one leaf instance), in file order: id `<id>/<node path>` (node_names.h),
/// group the part's group joined with the node path's parent, everything else
/// (units, transform, pieces, tags, motion, sag) the part's. Each distinct file
/// is read once, in loader processes (only node names cross the pipe), unless
/// the cache holds its node paths. A file
/// that cannot be read leaves its part whole with `error` set (the rest of the
/// batch goes on). Then validate_scene: an id clash names both parts
/// (SceneError). Forks: call it from a process with one thread.
void split_node_parts(SceneSpec& s, const SplitLoad& load = {});

/// Whether `id` lies under a part that split_node_parts has still to split
/// ("<split part id>/..."): validate_scene takes it as known until then.
bool under_unsplit_part(const SceneSpec& s, const std::string& id);

}  // namespace pd
