// One way for the tests to run a shell command: its stdout, its stderr (through
// a per-process file: ctest runs tests in parallel processes) and its wait status.
// Callers read the status as they need (exit code, signal).
#pragma once

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace pd_test {

/// The pdcheck executable for a run under the shell assignments `env`: the
/// fault-injecting one (tests/pdcheck_faults.cpp) when they set a
/// PDCHECK_TEST_* variable, else the product's.
inline std::string pdcheck_binary_for(const std::string& env) {
  return env.find("PDCHECK_TEST_") != std::string::npos ? PDCHECK_FAULTS_BINARY : PDCHECK_BINARY;
}

struct Captured {
  int status = -1;  ///< as from pclose (use WIFEXITED / WEXITSTATUS / WIFSIGNALED)
  std::string out, err;
};

/// Runs `cmd` (no redirections of its own for stderr) with stderr sent to `err_file`,
/// which is read and removed.
inline Captured run_capture(const std::string& cmd, const std::string& err_file) {
  Captured r;
  FILE* p = popen((cmd + " 2>'" + err_file + "'").c_str(), "r");
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
  r.status = pclose(p);
  std::ifstream e(err_file);
  std::stringstream ss;
  ss << e.rdbuf();
  r.err = ss.str();
  e.close();
  std::remove(err_file.c_str());
  return r;
}

}  // namespace pd_test
