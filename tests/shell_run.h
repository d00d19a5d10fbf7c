// Running the pdcheck binary from a shell script in the tests: exit code,
// stdout and stderr, and a scratch directory under the build tree.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "run_capture.h"
#include "scratch_dir.h"

namespace pd_test {

struct ShellRun {
  int code = -1;  ///< exit code, or 128 + signal as a shell reports it
  std::string out, err;
};

inline const std::string kPdcheck = PDCHECK_BINARY;
inline const std::string kDemo = std::string(PDCHECK_SOURCE_DIR) + "/testdata/demo/scene.json";

/// A fresh empty directory for one test, under the build tree.
inline std::string scratch_dir(const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(kPdcheck).parent_path().parent_path() / "test-scratch" /
                       (name + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

/// Runs `script` with /bin/sh in `dir`; "$PDCHECK" and "$DEMO" name the binary
/// and the demo scene, "$PDCHECK_FAULTS" the fault-injecting binary
/// (tests/pdcheck_faults.cpp). Stdin is /dev/null unless the script redirects it.
inline ShellRun shell(const std::string& dir, const std::string& script) {
  const std::string err_file = dir + "/.stderr";
  const std::string cmd = "cd '" + dir + "' && PDCHECK='" + kPdcheck + "' PDCHECK_FAULTS='" +
                          pdcheck_binary_for("PDCHECK_TEST_") + "' DEMO='" + kDemo +
                          "' /bin/sh -c '" + script + "' </dev/null";
  Captured c = run_capture(cmd, err_file);
  ShellRun r;
  r.code = WIFEXITED(c.status) ? WEXITSTATUS(c.status) : -1;
  r.out = std::move(c.out);
  r.err = std::move(c.err);
  return r;
}

}  // namespace pd_test
