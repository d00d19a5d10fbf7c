#include "check_command.h"

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>

#include "batch/empty_input.h"
#include "memory_limit.h"
#include "report/report_json.h"
#include "report/review_json.h"
#include "report/warning_lines.h"
#include "report/write_html.h"
#include "report/writer.h"
#include "say.h"

namespace {

// A number option within [lo, hi] (NaN is not), else `message` (CLI11 puts the
// option's name before it). `shown`: the --help text after the type.
CLI::Validator in_range(double lo, double hi, const std::string& message,
                        const std::string& shown = "") {
  return CLI::Validator(
      [=](std::string& text) {
        double x = 0.0;
        const bool number = CLI::detail::lexical_cast(text, x);
        return number && x >= lo && x <= hi ? std::string() : message;
      },
      shown);
}

}  // namespace

CheckCommand::CheckCommand(CLI::App& app) : app_(app) {
  pd::CheckArgs& a = args_;
  a.jobs = 0;
  app.add_option("scene", a.scene,
                 "scene JSON file, or - for standard input (a scene JSON or "
                 "a part list: one mesh path per line, or id<TAB>path)");
  app.add_option("--tolerance", a.tolerance,
                 "depth at or below which an interference is a discretization false positive, in "
                 "the scene's unit or with a unit suffix (0.05mm, 0.002in); overrides the scene. "
                 "Or auto: each pair's own band from its parts' measured tessellation sag where "
                 "they meet (docs/numerics.md)");
  app.add_option("--units", a.units,
                 "length unit of input that declares none (a part list, a scene without "
                 "\"units\"): mm, cm, m, in, ft; a scene declaring another unit is refused");
  app.add_option("--method", a.method,
                 "depth method: mlsl (default), mlsl-paper, gs-local, grid, exact");
  app.add_option("--pieces", a.pieces,
                 "convex pieces of every mesh part, overriding the scene: auto (default: the "
                 "hull, refined where the hull stage flags a nonconvex part), hull (never "
                 "refined), meshes, decompose");
  app.add_option("--cache", a.cache_dir,
                 "directory of cached decompositions (default: $XDG_CACHE_HOME/pdcheck or "
                 "~/.cache/pdcheck)");
  app.add_flag("--no-cache", a.no_cache, "neither read nor write cached decompositions");
  app.add_option("--seed", a.seed, "random seed of the stochastic methods (default 1)")
      ->check(CLI::Validator(
          [](std::string& v) { return std::string(v.rfind("-", 0) == 0 ? "must be >= 0" : ""); },
          "UINT"));
  app.add_option("-o,--output", output_,
                 "write the report to this file (atomically) instead of stdout");
  std::vector<std::string> format_names;
  for (const auto& f : pd::report_formats()) format_names.push_back(f.name);
  app.add_option("--format", a.format,
                 "report format: json (one document; the default, but for a terminal), jsonl (a "
                 "line per pair as it finishes, then a summary), junit, sarif, or table (the "
                 "verdict and a short table of the findings: the default when stdout is a "
                 "terminal and there is no -o)")
      ->check(CLI::IsMember(format_names));
  app.add_option(
         "-j,--jobs", a.jobs,
         "worker processes for the solves, threads for parsing and hulls (default: all cores)")
      ->check(CLI::Range(1, 4096));
  app.add_option("--pair-timeout", a.pair_timeout,
                 "seconds one pair may take before its worker is killed and the pair reported as "
                 "an error (default: none)")
      ->check(in_range(0, std::numeric_limits<double>::max(),
                       "must be a finite number of seconds (0 = none)", "NONNEGATIVE"));
  app.add_option("--load-timeout", a.load_timeout,
                 "seconds one mesh file may take to read before its loader process is killed and "
                 "its parts reported as errors (default: " +
                     std::to_string(int(pd::kDefaultLoadTimeout)) + "; 0: none)")
      ->check(in_range(0, 1e6, "must be a number of seconds from 0 to 1e6"));
  app.add_option("--load-memory", a.load_memory,
                 "MB one mesh loader process may allocate before its file is reported as an "
                 "error (default: half the machine's memory shared among the loaders; 0: none)")
      ->check(in_range(0, 1e9, "must be a number of MB from 0 to 1e9"));
  app.add_option("--memory", a.memory,
                 "memory the run keeps part surfaces in for reuse across their pairs (512M, 2G; "
                 "default: an eighth of the machine's, from 256M to 1G); what the pairs being "
                 "solved need comes on top (docs/performance.md)")
      ->check([](const std::string& v) {
        try {
          pd::parse_memory_mb(v);
          return std::string();
        } catch (const std::exception& e) {
          return std::string(e.what()).substr(std::string("--memory: ").size());
        }
      });
  app.add_flag("-q,--quiet", a.quiet, "no progress and no summary line on stderr");
  app.add_flag("--allow-empty", a.allow_empty,
               "accept an input with nothing to check (no parts, an empty part list, every part "
               "failed) instead of exit 2");
  add_ci_options(app, ci_);
  app.add_option("--shard", shard_,
                 "K/N: check shard K of N (a deterministic, cost-balanced share of the pairs; "
                 "loads only their parts), or auto (CI_NODE_INDEX/CI_NODE_TOTAL, or "
                 "SLURM_ARRAY_TASK_ID with --shard-total); merge with pdcheck merge "
                 "(docs/scale-out.md)");
  app.add_option("--shard-total", a.shard_total, "--shard auto under Slurm: the array's size N");
  app.add_option("--shard-base", a.shard_base,
                 "--shard auto under Slurm: the array's first index (default "
                 "SLURM_ARRAY_TASK_MIN, else 0)");
  app.add_option("--rules", a.rules,
                 "a rules file (sets, tests, ignore, expected, pairs; docs/scene-format.md, "
                 "\"Rules\"): the scene's \"rules\" key given apart");
  app.add_option("--reuse", a.reuse,
                 "an earlier JSON report: pairs whose parts and settings are unchanged keep "
                 "their results (marked reused) instead of being solved again (a report in another "
                 "unit is refused)");
}

int CheckCommand::run(const pd::FaultHooks& faults) {
  pd::CheckArgs& a = args_;
  if (a.scene.empty())
    throw pd::UserError(
        "a scene is required (a scene JSON file, or - for standard input); see --help");
  if (app_.count("--output")) a.output = output_;
  // For people at a terminal, a table; for programs (stdout piped or
  // redirected, as gh and ls decide) the JSON report, as when asked for.
  if (!app_.count("--format") && !app_.count("--output") && !app_.count("--shard") &&
      isatty(STDOUT_FILENO))
    a.format = "table";
  if (app_.count("--shard")) a.shard = shard_;
  a.extra = extra_output_paths(app_, ci_);
  a.review = ci_.review;
  a.jobs = jobs();
  pd::RunConfig config;
  pd::resolve_run_config(
      a, std::cin, [](const char* v) { return std::getenv(v); }, config);
  pd::RunOptions opt = config.options;
  opt.reuse = config.prior ? &*config.prior : nullptr;
  opt.faults = faults;
  if (!a.quiet) opt.on_warning = [](const std::string& w) { say("warning", w); };
  if (!a.quiet)
    for (const auto& w : config.prior_warnings) say("warning", w);
  const pd::ReviewOptions& review_opt = config.review.options;
  const bool jsonl = a.format == "jsonl";
  if (jsonl && !config.out_file) {
    // A failed write (the reader gone) throws: the run stops and its workers end.
    opt.on_pair = [&review_opt](const pd::PairResult& r, const std::vector<pd::Part>& parts) {
      auto j = pd::pair_json(r, parts);
      // The bar does not show in a pair line: any will do before the run's end.
      pd::add_pair_review(j, pd::review_pair(r, parts, review_opt, pd::FailOn::kNone));
      pd::write_stdout(j.dump() + "\n");
    };
  }
  pd::RunResult result;
  try {
    result = pd::run_scene(config.scene, opt);
  } catch (const pd::OutputError& e) {
    throw pd::UserError(std::string(e.what()) + "; the run stopped", e.exit_code());
  }
  const pd::Summary summary = pd::summarize(result);
  const pd::ReportContext ctx{config.scene.path,
                              config.scene.units.value_or("mm"),
                              *config.scene.tolerance,
                              opt.solver,
                              config.load_seconds,
                              config.scene.auto_tolerance,
                              result.rules ? result.rules->hash : ""};
  const pd::Review review = pd::review_run(result, review_opt, summary.incomplete());
  const pd::ReportInput report{ctx, result, review, review_opt};
  // Streamed lines are out already; a file gets the same lines in report order.
  const std::string text = jsonl && !config.out_file
                               ? pd::jsonl_tail(report) + "\n"
                               : pd::find_report_format(a.format)->render(report);
  if (config.out_file)
    pd::write_output_file(*config.out_file, text);
  else
    pd::write_stdout(text);
  pd::write_extra_outputs(config.extra, report, [&] { return pd::render_html(report); });
  if (!a.quiet)
    for (const auto& w : pd::warning_lines(result)) say("warning", w);
  for (const auto& p : result.parts)
    if (p.error) say("error", "part \"" + p.id + "\": " + *p.error);
  if (!a.quiet) {
    say_review(report);
    std::cerr << pd::summary_line(summary, result.seconds) << "\n";
    if (result.reuse) std::cerr << pd::reuse_line(*result.reuse, a.reuse) << "\n";
    if (config.prior && config.prior->settings_hash != result.settings_hash)
      say("warning", "--reuse " + a.reuse +
                         ": its settings hash differs from this run's (solver settings, tolerance "
                         "or checks): no pair was reused");
  }
  // A shard's verdict is the merge's: its exit code (as its report's) says
  // its report is written.
  if (review.deferred) {
    if (!a.quiet && review.own_exit_code != pd::kExitClean)
      say("note", "shard " + std::to_string(config.shard->index) + "/" +
                      std::to_string(config.shard->total) + ": " + std::to_string(review.failing) +
                      " failing finding(s) here; the verdict (exit code " +
                      std::to_string(review.own_exit_code) +
                      " for this shard alone) is pdcheck merge's: this shard exits 0");
    return review.exit_code;
  }
  if (review.exit_code == pd::kExitBadInput) say("error", *pd::every_part_failed(result));
  return review.exit_code;
}
