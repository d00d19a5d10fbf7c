// `pdcheck html REPORT.json -o PAGE.html`: the HTML page of a saved report.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

class HtmlCommand {
 public:
  explicit HtmlCommand(CLI::App& app);  ///< adds the subcommand to `app`
  bool parsed() const { return cmd_->parsed(); }
  /// 0 written, 3 written but a part's geometry could not be read (named on
  /// stderr and on the page); throws a pd::UserError otherwise.
  int run(int jobs, double load_timeout, bool quiet) const;

 private:
  CLI::App* cmd_;
  std::string report_, page_, scene_;
};
