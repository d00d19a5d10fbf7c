// A run that checked nothing because no part could be used: the CLI refuses it
// (exit 2) unless --allow-empty, so a failed export upstream does not pass green.
#pragma once

#include <optional>
#include <string>

#include "batch/run_result.h"

namespace pd {

/// Why the run checked nothing: it has parts and every one failed (each
/// named with its error in the report). nullopt when some part was usable or
/// there is no part (scene/scene.h, empty_scene_problem, says that case). A
/// shard's run holds only the parts it loaded: judge the merged run instead.
std::optional<std::string> every_part_failed(const RunResult& run);

}  // namespace pd
