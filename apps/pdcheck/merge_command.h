// `pdcheck merge`: shard reports into the report one run writes, with the
// run's CI outputs (docs/scale-out.md).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "ci_options.h"

class MergeCommand {
 public:
  explicit MergeCommand(CLI::App& app);  ///< adds the subcommand to `app`
  bool parsed() const { return cmd_->parsed(); }
  /// The exit code as the run's; 3 also when --html could not read a part's
  /// geometry again (named on stderr and on the page). Throws a pd::UserError
  /// on a bad shard, input or output.
  int run(int jobs, double load_timeout, bool quiet) const;

 private:
  CLI::App* cmd_;
  std::vector<std::string> inputs_;
  std::string output_, scene_;
  bool quiet_ = false;
  bool allow_empty_ = false;
  CiOptions ci_;
};
