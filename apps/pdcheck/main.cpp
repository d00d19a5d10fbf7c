// pdcheck: batch interference checking with penetration depths.
// The CLI only parses options, calls the library and sets the exit code
// (apps/pdcheck/cli.h; main() is in pdcheck.cpp).
#include <signal.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <mutex>
#include <optional>
#include <sstream>

#include "batch/run.h"
#include "batch/shard.h"
#include "cache_file.h"
#include "cli.h"
#include "printable.h"
#include "report/extra_outputs.h"
#include "report/html_from_report.h"
#include "report/merge.h"
#include "report/output_file.h"
#include "report/prior_report.h"
#include "report/report_json.h"
#include "report/review_inputs.h"
#include "report/review_json.h"
#include "report/review_text.h"
#include "report/write_html.h"
#include "report/writer.h"
#include "results/exit_code.h"
#include "results/fingerprint.h"
#include "scene/scene.h"
#include "scene/units.h"
#include "termination.h"

namespace {

using pd::kExitBadInput;
// The report could not be delivered (path, full disk, closed pipe): like bad
// usage, the run's findings are not known to the caller.
constexpr pd::ExitCode kExitOutput = pd::kExitBadInput;

// --jobs as given, else every core.
int jobs_or_all_cores(int jobs) {
  return jobs > 0 ? jobs : static_cast<int>(std::max(1L, sysconf(_SC_NPROCESSORS_ONLN)));
}

// One line on stderr; input text in it (ids, paths) cannot forge another line.
void say(const char* level, const std::string& message) {
  std::cerr << "pdcheck: " << level << ": " << pd::printable(message) << "\n";
}

const char* kExamples = R"(Examples:
  pdcheck scene.json                      check a scene, JSON report on stdout
  pdcheck scene.json -o report.json       write the report atomically to a file
  find parts -name '*.stl' | pdcheck - --tolerance 0.05 --units mm --format jsonl
                                          a part list on stdin, one JSON line per pair
  pdcheck scene.json --quiet -o report.json || echo "exit $?"
                                          in CI: 0 clean, 1 genuine interference,
                                          2 bad input or usage, 3 some pair unchecked
  pdcheck scene.json -o report.json --baseline last.json --suppressions accepted.json \
      --fail-on new --junit junit.xml --sarif pdcheck.sarif
                                          nightly CI: fail only on new or changed findings
                                          (docs/ci.md)
)";

// A saved report's scene, read again for its page's 3D views.
pd::ScenePartsLoader scene_parts_loader(int jobs, double load_timeout) {
  return [jobs, load_timeout](const std::string& scene, const std::optional<std::string>& units,
                              std::optional<double> tolerance) {
    return pd::load_scene_parts(scene, units, tolerance, jobs, load_timeout);
  };
}

// `pdcheck html REPORT.json -o PAGE.html`: 0 written, 3 written but a part's
// geometry could not be read (named on stderr and on the page), 2 otherwise.
int html_command(const std::string& report, const std::string& page, int jobs, double load_timeout,
                 bool quiet) {
  try {
    const pd::OutputFile out = pd::check_output_file("-o", page);
    pd::check_html_assets();
    const pd::SavedReportPage made =
        pd::html_from_report(report, scene_parts_loader(jobs, load_timeout));
    for (const auto& p : made.problems) say("warning", p);
    pd::write_output_file(out, made.html);
    if (!quiet) std::cerr << "pdcheck: wrote " << pd::printable(page) << "\n";
    return made.problems.empty() ? pd::kExitClean : pd::kExitIncomplete;
  } catch (const pd::ReportInputError& e) {
    say("error", e.what());
  } catch (const pd::SceneError& e) {
    say("error", std::string(e.what()) + " (the scene of " + report + ")");
  } catch (const pd::HtmlAssetError& e) {
    say("error", e.what());
  } catch (const pd::OutputError& e) {
    say("error", e.what());
  }
  return kExitBadInput;
}

// The CI options of a run and of a merge (docs/ci.md).
struct CiOptions {
  pd::ReviewArgs review;
  std::string write_suppressions, junit, sarif, html;
};

void add_ci_options(CLI::App& app, CiOptions& o) {
  std::vector<std::string> bars;
  std::string bar_help = "which findings make the exit code 1:";
  for (const auto& f : pd::kFailOnNames) {
    bars.push_back(f.name);
    bar_help += std::string(" ") + f.name + " (" + f.meaning + ");";
  }
  bar_help += " default: interference, or clearance when the scene checks clearance";
  app.add_option("--fail-on", o.review.fail_on, bar_help)->check(CLI::IsMember(bars));
  app.add_option("--baseline", o.review.baseline,
                 "a previous JSON report: mark each finding new, unchanged or updated and list "
                 "the baseline's findings that are absent or unknown now");
  app.add_option("--suppressions", o.review.suppressions,
                 "reviewed suppressions (JSON, docs/ci.md): listed findings are reported as "
                 "suppressed and do not fail the run");
  app.add_flag("--allow-stale-suppressions", o.review.allow_stale,
               "a suppression that matched nothing or expired does not fail the run");
  app.add_option("--write-suppressions", o.write_suppressions,
                 "write a starting suppressions file for this run's findings (reasons to fill in)");
  app.add_option("--junit", o.junit, "also write JUnit XML to this file (atomically)");
  app.add_option("--sarif", o.sarif, "also write SARIF 2.1.0 to this file (atomically)");
  app.add_option("--html", o.html,
                 "also write a self-contained HTML page with a 3D view of every finding "
                 "(atomically; docs/report-format.md)");
}

pd::ExtraOutputPaths extra_output_paths(const CLI::App& app, const CiOptions& o) {
  pd::ExtraOutputPaths p;
  if (app.count("--junit")) p.junit = o.junit;
  if (app.count("--sarif")) p.sarif = o.sarif;
  if (app.count("--html")) p.html = o.html;
  if (app.count("--write-suppressions")) p.write_suppressions = o.write_suppressions;
  return p;
}

// The review on stderr, one escaped line at a time (ids in it).
void say_review(const pd::ReportInput& report) {
  std::istringstream review_text(pd::review_lines(report));
  for (std::string line; std::getline(review_text, line);) std::cerr << pd::printable(line) << "\n";
}

// pdcheck merge: shard reports into the report one run writes, with the run's
// CI outputs (docs/scale-out.md). Exit code as the run's; 3 also when --html
// could not read a part's geometry again (named on stderr and on the page).
int run_merge(const std::vector<std::string>& inputs, const std::string& output, bool to_file,
              const CiOptions& ci, const pd::ExtraOutputPaths& extra_paths, int jobs,
              double load_timeout, bool quiet) {
  try {
    std::optional<pd::OutputFile> out_file;
    if (to_file) out_file = pd::check_output_file("-o", output);
    const pd::ExtraOutputs extra = pd::check_extra_outputs(extra_paths);
    std::vector<pd::ShardReport> shards;
    for (const auto& path : inputs) shards.push_back(pd::read_shard_report(path));
    pd::ReviewInputs review;
    // The tolerance of the `updated` rule is the shards' (merge_shard_reports).
    pd::load_review_inputs(ci.review, 0.0, review);
    const pd::Merged m = pd::merge_shard_reports(shards, review.options);
    const std::string text = m.doc.dump(2) + "\n";
    if (out_file)
      pd::write_output_file(*out_file, text);
    else
      pd::write_stdout(text);
    const pd::ReportInput report{m.context, m.run, m.review, m.review_options};
    std::vector<std::string> page_problems;
    pd::write_extra_outputs(extra, report, [&] {
      const pd::SavedReportPage page = pd::html_from_report_document(
          nlohmann::json::parse(text), to_file ? output : inputs.front(),
          scene_parts_loader(jobs, load_timeout));
      page_problems = page.problems;
      return page.html;
    });
    for (const auto& p : page_problems) say("warning", p);
    if (!quiet) {
      say_review(report);
      std::cerr << m.summary_line << "\n";
    }
    return page_problems.empty() ? m.review.exit_code : pd::kExitIncomplete;
  } catch (const pd::MergeError& e) {
    say("error", std::string("merge: ") + e.what());
  } catch (const pd::ReportInputError& e) {
    say("error", e.what());
  } catch (const pd::ReviewArgsError& e) {
    say("error", e.what());
  } catch (const pd::SceneError& e) {  // --html: the shards' scene unreadable now
    say("error", std::string("--html: ") + e.what());
  } catch (const pd::OutputError& e) {
    say("error", e.what());
  } catch (const pd::HtmlAssetError& e) {
    say("error", e.what());
  }
  return kExitBadInput;
}

}  // namespace

int run_cli(int argc, char** argv, const pd::FaultHooks& faults) {
  CLI::App app{
      "pdcheck: convex interference checking with penetration depths (Abramson, Kent "
      "& Smith's MLSL + Ipopt), separating tessellation false positives from genuine "
      "interferences."};
  app.footer(kExamples);
  std::string scene_arg, output, format = "json", method_arg, units_arg, pieces_arg, cache_dir;
  bool no_cache = false;
  double tolerance = 0.0, pair_timeout = 0.0, load_timeout = pd::kDefaultLoadTimeout;
  double load_memory = pd::kAutoLoadMemory;
  int jobs = 0;
  std::uint64_t seed = 0;
  bool quiet = false;
  std::string html_report, html_page;
  app.add_option("scene", scene_arg,
                 "scene JSON file, or - for standard input (a scene JSON or "
                 "a part list: one mesh path per line, or id<TAB>path)");
  app.add_option("--tolerance", tolerance,
                 "depth at or below which an interference is a discretization false positive "
                 "(scene units; overrides the scene)");
  app.add_option("--units", units_arg,
                 "length unit of the scene and the report: mm, cm, m, in, ft");
  app.add_option("--method", method_arg,
                 "depth method: mlsl (default), mlsl-paper, gs-local, grid, exact");
  app.add_option("--pieces", pieces_arg,
                 "convex pieces of every mesh part, overriding the scene: auto (default: the "
                 "hull, refined where the hull stage flags a nonconvex part), hull (never "
                 "refined), meshes, decompose");
  app.add_option("--cache", cache_dir,
                 "directory of cached decompositions (default: $XDG_CACHE_HOME/pdcheck or "
                 "~/.cache/pdcheck)");
  app.add_flag("--no-cache", no_cache, "neither read nor write cached decompositions");
  app.add_option("--seed", seed, "random seed of the stochastic methods (default 1)")
      ->check(CLI::Validator(
          [](std::string& v) { return std::string(v.rfind("-", 0) == 0 ? "must be >= 0" : ""); },
          "UINT"));
  app.add_option("-o,--output", output,
                 "write the report to this file (atomically) instead of stdout");
  std::vector<std::string> format_names;
  for (const auto& f : pd::report_formats()) format_names.push_back(f.name);
  app.add_option("--format", format,
                 "report format: json (one document), jsonl (a line per pair as it finishes, "
                 "then a summary), junit or sarif")
      ->check(CLI::IsMember(format_names));
  app.add_option(
         "-j,--jobs", jobs,
         "worker processes for the solves, threads for parsing and hulls (default: all cores)")
      ->check(CLI::Range(1, 4096));
  app.add_option("--pair-timeout", pair_timeout,
                 "seconds one pair may take before its worker is killed and the pair reported as "
                 "an error (default: none)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--load-timeout", load_timeout,
                 "seconds one mesh file may take to read before its loader process is killed and "
                 "its parts reported as errors (default: " +
                     std::to_string(int(pd::kDefaultLoadTimeout)) + "; 0: none)");
  app.add_option("--load-memory", load_memory,
                 "MB one mesh loader process may allocate before its file is reported as an "
                 "error (default: half the machine's memory shared among the loaders; 0: none)");
  app.add_flag("-q,--quiet", quiet, "no progress and no summary line on stderr");
  CiOptions ci;
  add_ci_options(app, ci);
  CLI::App* html_cmd = app.add_subcommand(
      "html",
      "write the HTML page of a saved JSON report, reading its scene's meshes again "
      "(exit 3: written, but a part could not be read)");
  html_cmd->add_option("report", html_report, "a JSON report (--format json)")->required();
  html_cmd->add_option("-o,--output", html_page, "the HTML file to write (atomically)")->required();
  html_cmd->fallthrough();  // -j, --load-timeout, -q after the subcommand
  std::string shard_arg, reuse_path;
  std::optional<int> shard_total, shard_base;
  app.add_option("--shard", shard_arg,
                 "K/N: check shard K of N (a deterministic, cost-balanced share of the pairs; "
                 "loads only their parts), or auto (CI_NODE_INDEX/CI_NODE_TOTAL, or "
                 "SLURM_ARRAY_TASK_ID with --shard-total); merge with pdcheck merge "
                 "(docs/scale-out.md)");
  app.add_option("--shard-total", shard_total, "--shard auto under Slurm: the array's size N");
  app.add_option("--shard-base", shard_base,
                 "--shard auto under Slurm: the array's first index (default "
                 "SLURM_ARRAY_TASK_MIN, else 0)");
  app.add_option("--reuse", reuse_path,
                 "an earlier JSON report: pairs whose parts and settings are unchanged keep "
                 "their results (marked reused) instead of being solved again");
  CLI::App* merge_cmd = app.add_subcommand(
      "merge", "merge shard reports (--shard K/N) into the report one run writes");
  std::vector<std::string> merge_inputs;
  std::string merge_output;
  bool merge_quiet = false;
  CiOptions merge_ci;
  merge_cmd->add_option("reports", merge_inputs, "the shard reports, 1..N, each once")->required();
  merge_cmd->add_option("-o,--output", merge_output,
                        "write the merged report to this file (atomically) instead of stdout");
  add_ci_options(*merge_cmd, merge_ci);
  merge_cmd->add_flag("-q,--quiet", merge_quiet, "no review and no summary line on stderr");
  merge_cmd->fallthrough();  // -j, --load-timeout (--html reads the meshes again)
  app.set_version_flag("--version", std::string("pdcheck ") + PDCHECK_VERSION);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? pd::kExitClean : kExitBadInput;
  }
  // Write errors are reported as errors (EPIPE), not a silent death; a
  // terminated run takes its workers and temporary files with it.
  signal(SIGPIPE, SIG_IGN);
  pd::install_termination_handlers();
  if (html_cmd->parsed())
    return html_command(html_report, html_page, jobs_or_all_cores(jobs), load_timeout, quiet);
  if (merge_cmd->parsed())
    return run_merge(merge_inputs, merge_output, merge_cmd->count("--output") > 0, merge_ci,
                     extra_output_paths(*merge_cmd, merge_ci), jobs_or_all_cores(jobs),
                     load_timeout, merge_quiet || quiet);
  if (scene_arg.empty()) {
    say("error", "a scene is required (a scene JSON file, or - for standard input); see --help");
    return kExitBadInput;
  }
  std::optional<pd::ShardSpec> shard;
  try {
    if (shard_arg == "auto") {
      shard = pd::shard_from_environment([](const char* v) { return std::getenv(v); }, shard_total,
                                         shard_base);
    } else {
      if (shard_total || shard_base)
        throw pd::ShardError("--shard-total and --shard-base go with --shard auto");
      if (app.count("--shard")) shard = pd::parse_shard(shard_arg);
    }
    if (shard) {
      if (format != "json")
        throw pd::ShardError("--shard writes a JSON report (--format json) for pdcheck merge");
      for (const char* o :
           {"--baseline", "--suppressions", "--write-suppressions", "--junit", "--sarif", "--html"})
        if (app.count(o))
          throw pd::ShardError(std::string("--shard: ") + o +
                               " applies to the whole run, not to one shard");
    }
  } catch (const pd::ShardError& e) {
    say("error", e.what());
    return kExitBadInput;
  }
  if (!std::isfinite(pair_timeout)) {
    say("error", "--pair-timeout: must be a finite number of seconds (0 = none)");
    return kExitBadInput;
  }
  // Every output path is checked before the run: a bad one fails now, not
  // after hours of solving.
  std::optional<pd::OutputFile> out_file;
  pd::ExtraOutputs extra;
  try {
    if (app.count("--output")) out_file = pd::check_output_file("-o", output);
    extra = pd::check_extra_outputs(extra_output_paths(app, ci));
  } catch (const pd::OutputError& e) {
    say("error", e.what());
    return kExitOutput;
  } catch (const pd::HtmlAssetError& e) {
    say("error", e.what());
    return kExitOutput;
  }

  if (!(load_timeout >= 0 && load_timeout <= 1e6)) {
    say("error", "--load-timeout: must be a number of seconds from 0 to 1e6");
    return kExitBadInput;
  }
  if (app.count("--load-memory") && !(load_memory >= 0 && load_memory <= 1e9)) {
    say("error", "--load-memory: must be a number of MB from 0 to 1e9");
    return kExitBadInput;
  }
  jobs = jobs_or_all_cores(jobs);
  pd::SceneSpec scene;
  pd::SolverSettings solver;
  const auto load_start = std::chrono::steady_clock::now();
  try {
    std::optional<std::string> units;
    if (!units_arg.empty()) {
      if (!pd::unit_in_mm(units_arg))
        throw pd::SceneError("--units: unknown unit \"" + units_arg + "\" (use " + pd::kUnitNames +
                             ")");
      units = units_arg;
    }
    if (scene_arg == "-") {
      std::string text{std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>()};
      scene = pd::parse_stdin_scene(text, units, jobs);
    } else {
      scene = pd::load_scene_file(scene_arg, units, jobs, /*keep_vertices=*/!shard);
    }
    if (app.count("--tolerance")) {
      if (!(tolerance > 0 && std::isfinite(tolerance)))
        throw pd::SceneError("--tolerance: must be a finite number > 0");
      scene.tolerance = tolerance;
    }
    if (!scene.tolerance)
      throw pd::SceneError(scene.path +
                           ": no tolerance: give \"tolerance\" in the scene or --tolerance");
    scene.solver.apply(solver);
    if (!method_arg.empty()) {
      const auto m = pd::parse_method(method_arg);
      if (!m)
        throw pd::SceneError("--method: unknown method \"" + method_arg +
                             "\" (mlsl, mlsl-paper, gs-local, grid, exact)");
      solver.method = *m;
    }
    if (app.count("--seed")) solver.seed = seed;
    if (!pieces_arg.empty()) {
      const auto p = pd::parse_pieces(pieces_arg);
      if (!p)
        throw pd::SceneError("--pieces: unknown value \"" + pieces_arg + "\" (use " +
                             pd::kPiecesNames + ")");
      pd::override_pieces(scene, *p);
    }
  } catch (const pd::SceneError& e) {
    say("error", e.what());
    return kExitBadInput;
  }

  // The CI inputs are read before the run: a malformed file costs no solve.
  std::optional<pd::PriorResults> prior;
  pd::ReviewInputs review_in;
  pd::ReviewOptions& review_opt = review_in.options;
  try {
    if (!reuse_path.empty()) prior = pd::load_prior_report(reuse_path);
    pd::load_review_inputs(ci.review, *scene.tolerance, review_in);
  } catch (const pd::ReportInputError& e) {
    say("error", e.what());
    return kExitBadInput;
  } catch (const pd::ReviewArgsError& e) {
    say("error", e.what());
    return kExitBadInput;
  }
  if (scene.pairs) {
    review_opt.listed.emplace();
    for (const auto& [a, b] : *scene.pairs) review_opt.listed->insert(pd::pair_fingerprint(a, b));
  }

  const double load_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start).count();
  pd::RunOptions opt;
  opt.solver = solver;
  opt.tolerance = *scene.tolerance;
  opt.jobs = jobs;
  opt.pair_timeout = pair_timeout;
  opt.load_timeout = load_timeout;
  opt.load_memory_mb = load_memory;
  opt.quiet = quiet;
  opt.shard = shard;
  opt.reuse = prior ? &*prior : nullptr;
  opt.faults = faults;
  if (!quiet) opt.on_warning = [](const std::string& w) { say("warning", w); };
  if (!no_cache) opt.cache_dir = cache_dir.empty() ? pd::default_cache_dir() : cache_dir;
  const bool jsonl = format == "jsonl";
  if (jsonl && !out_file) {
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
    result = pd::run_scene(scene, opt);
  } catch (const pd::OutputError& e) {
    say("error", std::string(e.what()) + "; the run stopped");
    return kExitOutput;
  } catch (const pd::SceneError& e) {  // a shard's scene file changed under it
    say("error", e.what());
    return kExitBadInput;
  }
  const pd::Summary summary = pd::summarize(result);
  pd::ReportContext ctx{scene.path, scene.units.value_or("mm"), *scene.tolerance, solver,
                        load_seconds};

  const pd::Review review = pd::review_run(result, review_opt, summary.incomplete());
  const pd::ReportInput report{ctx, result, review, review_opt};

  // Streamed lines are out already; a file gets the same lines in report order.
  const std::string text = jsonl && !out_file ? pd::jsonl_tail(report) + "\n"
                                              : pd::find_report_format(format)->render(report);
  try {
    if (out_file)
      pd::write_output_file(*out_file, text);
    else
      pd::write_stdout(text);
    pd::write_extra_outputs(extra, report, [&] { return pd::render_html(report); });
  } catch (const pd::OutputError& e) {
    say("error", e.what());
    return kExitOutput;
  } catch (const pd::HtmlAssetError& e) {  // the library removed during the run
    say("error", e.what());
    return kExitOutput;
  }
  for (const auto& p : result.parts) {
    if (!quiet)
      for (const auto& w : p.warnings) say("warning", "part \"" + p.id + "\": " + w);
    if (p.error) say("error", "part \"" + p.id + "\": " + *p.error);
  }
  if (!quiet) {
    say_review(report);
    std::cerr << pd::summary_line(summary, result.seconds) << "\n";
    if (result.reused)
      std::cerr << "pdcheck: " << result.reused << " pair(s) reused from " << reuse_path << "\n";
  }
  // A shard's verdict is the merge's: its exit code says its report is written.
  if (shard) return pd::kExitClean;
  return review.exit_code;
}
