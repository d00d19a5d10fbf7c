// `pdcheck SCENE`: check a scene (the command without a subcommand). Its
// options also serve the subcommands that fall through to it (-j,
// --load-timeout, -q).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "batch/run.h"
#include "ci_options.h"
#include "report/run_config.h"
#include "say.h"

class CheckCommand {
 public:
  explicit CheckCommand(CLI::App& app);  ///< adds the options to `app`
  /// The exit code of the run (0 for a shard: its verdict is the merge's);
  /// throws a pd::UserError on bad usage, input or output.
  int run(const pd::FaultHooks& faults);

  int jobs() const { return jobs_or_all_cores(args_.jobs); }  ///< -j, else every core
  double load_timeout() const { return args_.load_timeout; }
  bool quiet() const { return args_.quiet; }

 private:
  CLI::App& app_;
  pd::CheckArgs args_;
  std::string output_, shard_;
  CiOptions ci_;
};
