// pdcheck: batch interference checking with penetration depths. The command
// line only: each command in its own file (check_command, html_command,
// merge_command) parses its options and calls the library; a user error of
// any of them is said here once, with the exit code it carries.
#include "cli.h"

#include <signal.h>

#include <CLI/CLI.hpp>

#include "check_command.h"
#include "html_command.h"
#include "merge_command.h"
#include "say.h"
#include "termination.h"
#include "usage_error.h"
#include "user_error.h"

namespace {

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

}  // namespace

int run_cli(int argc, char** argv, const pd::FaultHooks& faults) {
  CLI::App app{
      "pdcheck: convex interference checking with penetration depths (Abramson, Kent "
      "& Smith's MLSL + Ipopt), separating tessellation false positives from genuine "
      "interferences."};
  app.footer(kExamples);
  CheckCommand check(app);
  const HtmlCommand html(app);
  const MergeCommand merge(app);
  app.set_version_flag("--version", std::string("pdcheck ") + PDCHECK_VERSION);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e) == 0 ? pd::kExitClean : pd::kExitBadInput;
    // Like every other message: "pdcheck: error: …", a typo's nearest option.
    say("error", usage_message(e, app) + " (pdcheck --help lists the options)");
    return pd::kExitBadInput;
  }
  // Write errors are reported as errors (EPIPE), not a silent death; a
  // terminated run takes its workers and temporary files with it.
  signal(SIGPIPE, SIG_IGN);
  pd::install_termination_handlers();
  try {
    if (html.parsed()) return html.run(check.jobs(), check.load_timeout(), check.quiet());
    if (merge.parsed()) return merge.run(check.jobs(), check.load_timeout(), check.quiet());
    return check.run(faults);
  } catch (const pd::UserError& e) {
    say("error", e.what());
    return e.exit_code();
  }
}
