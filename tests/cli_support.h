// Running the pdcheck binary and the external validators from tests.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "run_capture.h"
#include "scratch_dir.h"

namespace pd::test {

inline const std::string kSource = PDCHECK_SOURCE_DIR;

struct CliResult {
  int code = -1;   ///< exit code, or -1 when killed by a signal
  int signal = 0;  ///< the signal that ended it, if any
  std::string out, err;
};

using pd_test::read_text;

using pd_test::process_dir;

/// `text` written to `name` in this process's own directory; its path.
inline std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = process_dir() + name;
  std::ofstream(path) << text;
  return path;
}

/// A shell command: exit code, stdout, and stderr (through a per-process file:
/// ctest runs tests in parallel processes).
inline CliResult shell(const std::string& cmd) {
  const std::string err_file = testing::TempDir() + "cli_err_" + std::to_string(getpid()) + ".txt";
  pd_test::Captured c = pd_test::run_capture(cmd + " </dev/null", err_file);
  CliResult r;
  r.code = WIFEXITED(c.status) ? WEXITSTATUS(c.status) : -1;
  r.out = std::move(c.out);
  r.err = std::move(c.err);
  return r;
}

/// pdcheck with `stdin_text` on its standard input (none: /dev/null) and the
/// shell assignments `env` before it. The shell execs it, so a signal that
/// ends it is reported as such (a shell would exit with 128 + the signal).
inline CliResult pdcheck(const std::string& args, const std::string& stdin_text = "",
                         const std::string& env = "") {
  const std::string tag = std::to_string(getpid());  // ctest runs tests in parallel processes
  const std::string err_file = testing::TempDir() + "pdcheck_err_" + tag + ".txt";
  std::string cmd = env + " exec " + pd_test::pdcheck_binary_for(env) + " " + args;
  if (!stdin_text.empty()) {
    const std::string in_file = testing::TempDir() + "pdcheck_in_" + tag + ".txt";
    std::ofstream(in_file) << stdin_text;
    cmd += " <" + in_file;
  } else {
    cmd += " </dev/null";
  }
  const pd_test::Captured c = pd_test::run_capture(cmd, err_file);
  CliResult r;
  r.out = c.out;
  r.err = c.err;
  if (WIFEXITED(c.status) && WEXITSTATUS(c.status) > 128) r.signal = WEXITSTATUS(c.status) - 128;
  if (WIFSIGNALED(c.status)) r.signal = WTERMSIG(c.status);
  r.code = WIFEXITED(c.status) && !r.signal ? WEXITSTATUS(c.status) : -1;
  return r;
}

inline bool have_command(const std::string& name) {
  return shell("command -v " + name + " >/dev/null").code == 0;
}

/// JSON Schema validation by python3-jsonschema (tests/validate_json.py): ""
/// when valid, else the errors. Sets `skip` when the validator is missing.
inline std::string validate_json(const std::string& schema, const std::string& doc, bool& skip) {
  const CliResult r = shell("python3 " + kSource + "/tests/validate_json.py " + schema + " " + doc);
  skip = r.code == 77 || r.code == 127;
  return r.code == 0 ? "" : r.err + " (exit " + std::to_string(r.code) + ")";
}

/// XSD validation by xmllint: "" when valid, else its messages.
inline std::string validate_xml(const std::string& xsd, const std::string& doc) {
  const CliResult r = shell("xmllint --noout --schema " + xsd + " " + doc);
  return r.code == 0 ? "" : r.err + " (exit " + std::to_string(r.code) + ")";
}

}  // namespace pd::test

/// Skips the current test, saying which tool is missing and what installs it.
#define PD_REQUIRE_TOOL(ok, what)                                                          \
  do {                                                                                     \
    if (!(ok)) GTEST_SKIP() << what << " is not installed (scripts/setup.sh installs it)"; \
  } while (0)
