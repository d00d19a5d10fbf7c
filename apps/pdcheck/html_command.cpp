#include "html_command.h"

#include <iostream>
#include <optional>

#include "printable.h"
#include "report/output_file.h"
#include "report/write_html.h"
#include "say.h"
#include "scene/scene.h"

HtmlCommand::HtmlCommand(CLI::App& app) {
  cmd_ = app.add_subcommand(
      "html",
      "write the HTML page of a saved JSON report, reading its scene's meshes again "
      "(exit 3: written, but a part could not be read)");
  cmd_->add_option("report", report_, "a JSON report (--format json)")->required();
  cmd_->add_option("-o,--output", page_, "the HTML file to write (atomically)")->required();
  cmd_->add_option("--scene", scene_,
                   "the scene file the report was made from, where the report's own path to it "
                   "no longer leads (a report moved or downloaded as a CI artefact)");
  cmd_->fallthrough();  // -j, --load-timeout, -q after the subcommand
}

int HtmlCommand::run(int jobs, double load_timeout, bool quiet) const {
  const pd::OutputFile out = pd::check_output_file("-o", page_);
  pd::check_html_assets();
  pd::SavedReportPage made;
  try {
    made = pd::html_from_report(
        report_, scene_parts_loader(jobs, load_timeout),
        cmd_->count("--scene") ? std::optional<std::string>(scene_) : std::nullopt);
  } catch (const pd::SceneError& e) {
    throw pd::UserError(std::string(e.what()) + " (the scene of " + report_ + ")");
  }
  for (const auto& p : made.problems) say("warning", p);
  pd::write_output_file(out, made.html);
  if (!quiet) std::cerr << "pdcheck: wrote " << pd::printable(page_) << "\n";
  return made.problems.empty() ? pd::kExitClean : pd::kExitIncomplete;
}
