#include "merge_command.h"

#include <iostream>
#include <optional>

#include "batch/empty_input.h"
#include "report/merge.h"
#include "report/output_file.h"
#include "report/prior_settings.h"
#include "report/writer.h"
#include "say.h"
#include "scene/scene.h"

MergeCommand::MergeCommand(CLI::App& app) {
  cmd_ = app.add_subcommand("merge",
                            "merge shard reports (--shard K/N) into the report one run writes");
  cmd_->add_option("reports", inputs_, "the shard reports, 1..N, each once")->required();
  cmd_->add_option("-o,--output", output_,
                   "write the merged report to this file (atomically) instead of stdout");
  add_ci_options(*cmd_, ci_);
  cmd_->add_option("--scene", scene_,
                   "--html: the scene file the shards checked, where their reports' path to it "
                   "no longer leads");
  cmd_->add_flag("-q,--quiet", quiet_, "no review and no summary line on stderr");
  cmd_->add_flag("--allow-empty", allow_empty_,
                 "exit by the findings even when every part failed (else exit 2)");
  cmd_->fallthrough();  // -j, --load-timeout (--html reads the meshes again)
}

int MergeCommand::run(int jobs, double load_timeout, bool quiet) const {
  const bool to_file = cmd_->count("--output") > 0;
  std::optional<pd::OutputFile> out_file;
  if (to_file) out_file = pd::check_output_file("-o", output_);
  const pd::ExtraOutputs extra = pd::check_extra_outputs(extra_output_paths(*cmd_, ci_));
  std::vector<pd::ShardReport> shards;
  pd::ReviewInputs review;
  std::optional<pd::Merged> merged;
  try {
    for (const auto& path : inputs_) shards.push_back(pd::read_shard_report(path));
    // The tolerance of the `updated` rule is the shards' (merge_shard_reports).
    pd::load_review_inputs(ci_.review, 0.0, review);
    review.options.allow_empty = allow_empty_;
    merged.emplace(pd::merge_shard_reports(shards, review.options));
  } catch (const pd::MergeError& e) {
    throw pd::UserError(std::string("merge: ") + e.what());
  }
  const pd::Merged& m = *merged;
  if (review.baseline)  // refused in another unit, said when other settings
    for (const auto& w : pd::check_prior_settings("--baseline", review.baseline->path,
                                                  review.baseline->settings, m.context))
      if (!quiet && !quiet_) say("warning", w);
  const std::string text = m.doc.dump(2) + "\n";
  if (out_file)
    pd::write_output_file(*out_file, text);
  else
    pd::write_stdout(text);
  const pd::ReportInput report{m.context, m.run, m.review, m.review_options};
  std::vector<std::string> page_problems;
  try {
    pd::write_extra_outputs(extra, report, [&] {
      const pd::SavedReportPage page = pd::html_from_report_document(
          nlohmann::json::parse(text), to_file ? output_ : inputs_.front(),
          scene_parts_loader(jobs, load_timeout),
          cmd_->count("--scene") ? std::optional<std::string>(scene_) : std::nullopt);
      page_problems = page.problems;
      return page.html;
    });
  } catch (const pd::SceneError& e) {  // --html: the shards' scene unreadable now
    throw pd::UserError(std::string("--html: ") + e.what());
  }
  for (const auto& p : page_problems) say("warning", p);
  if (!quiet && !quiet_) {
    say_review(report);
    std::cerr << m.summary_line << "\n";
  }
  if (m.review.exit_code == pd::kExitBadInput)
    say("error", "merge: " + *pd::every_part_failed(m.run));
  return page_problems.empty() ? m.review.exit_code : pd::kExitIncomplete;
}
