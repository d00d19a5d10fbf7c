// Content hashes of a scene (src/hash.h, XXH3-128): what shards compare before
// they are merged, and what --reuse compares before it takes an old pair result.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "hash.h"
#include "scene/scene.h"
#include "solve/settings.h"

namespace pd {

/// Per part, the hash of everything its geometry depends on: the mesh file's bytes
/// (or the inline vertices' bits), its units, transform, pieces and motion. The
/// id is not in it (ids name pairs; a renamed part is another pair). A mesh file is
/// read once however many parts use it; an unreadable one hashes its path and the
/// reason, so it never matches a readable file.
std::vector<std::string> part_content_hashes(const SceneSpec& scene);
/// The same from the mesh files' hashes (mesh_file_hashes), reading no file.
std::vector<std::string> part_content_hashes(const SceneSpec& scene,
                                             const std::map<std::string, std::string>& files);

/// Each mesh file's content hash (path -> hash), each file read once; an
/// unreadable one hashes its path and the reason, so it never matches a readable file.
std::map<std::string, std::string> mesh_file_hashes(const SceneSpec& scene);

/// The scene: its unit, the parts (ids and content hashes, in order) and any pair list.
std::string scene_content_hash(const SceneSpec& scene, const std::vector<std::string>& part_hashes);

/// Adds every solver setting (solve/settings.h's for_each_setting): the method
/// by name, integers (the seed included) exactly as decimal text, doubles by
/// their bits. For every hash of the settings.
void add_solver_settings(Hasher& h, const SolverSettings& s);

/// Everything besides geometry that changes a pair's result: the solver settings,
/// the tolerance and the checks (clearance, motion).
/// `auto_tolerance`: tolerance auto and its clamps (each pair's band then
/// follows from its parts' content, which the part hashes hold).
std::string settings_hash(const SolverSettings& solver, double tolerance, const Checks& checks,
                          const std::optional<AutoTolerance>& auto_tolerance = std::nullopt);

}  // namespace pd
