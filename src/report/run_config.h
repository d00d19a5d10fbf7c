// A check run as its options ask for it (apps/pdcheck reads them into
// CheckArgs), resolved and checked before any solve: a bad value, file or
// output path fails now, not after hours of solving.
#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "batch/run.h"
#include "report/extra_outputs.h"
#include "report/output_file.h"
#include "report/review_inputs.h"
#include "scene/scene.h"

namespace pd {

/// The options as given ("" or nullopt: not given).
struct CheckArgs {
  std::string scene;  ///< a scene file, or - for standard input
  std::string units, method, pieces;
  std::optional<std::string> tolerance;  ///< a length ("0.05", "0.05mm"; scene/units.h) or "auto"
  std::optional<std::uint64_t> seed;
  std::string format = "json";
  std::optional<std::string> output;
  ExtraOutputPaths extra;
  ReviewArgs review;
  std::optional<std::string> shard;  ///< K/N or auto
  std::optional<int> shard_total, shard_base;
  std::string reuse;
  std::string rules;  ///< --rules FILE ("" = the scene's own, if any)
  int jobs = 1;       ///< resolved: every core when not given
  double pair_timeout = 0.0, load_timeout = kDefaultLoadTimeout, load_memory = kAutoLoadMemory;
  std::string memory;  ///< --memory: "512M", "2G", MB; "" = memory_budget_mb's share
  bool quiet = false;
  std::string cache_dir;  ///< "" = the default cache directory
  bool no_cache = false;
  bool allow_empty = false;  ///< --allow-empty: nothing to check is no error
};

/// The run to do. Not copyable: its review options point into its own files.
struct RunConfig {
  SceneSpec scene;
  std::optional<ShardSpec> shard;
  std::optional<OutputFile> out_file;  ///< -o, checked writable
  ExtraOutputs extra;                  ///< --junit, --sarif, --html, --write-suppressions
  std::optional<PriorResults> prior;   ///< --reuse
  ReviewInputs review;
  /// Everything but the callbacks, the fault hooks and `reuse` (which points
  /// into `prior`: set it where the run is made).
  RunOptions options;
  double load_seconds = 0.0;  ///< reading the scene and the CI inputs
  /// --reuse and --baseline written under other settings (report/prior_settings.h).
  std::vector<std::string> prior_warnings;

  RunConfig() = default;
  RunConfig(const RunConfig&) = delete;
  RunConfig& operator=(const RunConfig&) = delete;
};

/// Resolves `args` into `out`, in the order a user meets the problems: the
/// shard, the output paths, the scene (with --units, --tolerance, --method,
/// --seed, --pieces over it), then --reuse and the CI inputs. `in`: standard
/// input, for scene "-"; `getenv`: the environment, for --shard auto. Throws
/// a UserError (user_error.h) naming the option or file.
void resolve_run_config(const CheckArgs& args, std::istream& in,
                        const std::function<const char*(const char*)>& getenv, RunConfig& out);

}  // namespace pd
