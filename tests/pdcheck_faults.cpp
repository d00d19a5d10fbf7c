// pdcheck with faults injected into its worker processes, for the tests that
// need a crash or a stall in a real run (the product reads no such variable):
//   PDCHECK_TEST_CRASH_PAIR=A:B     the worker solving parts A and B aborts
//   PDCHECK_TEST_PAIR_SLEEP_MS=N    every pair takes N ms longer
//   PDCHECK_TEST_CRASH_MESH=NAME    the loader reading a path ending in NAME aborts
//   PDCHECK_TEST_HANG_MESH=NAME     ... hangs
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include "cli.h"

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return !tail.empty() && s.size() >= tail.size() &&
         s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v ? v : "";
}

}  // namespace

int main(int argc, char** argv) {
  pd::FaultHooks faults;
  const std::string crash_pair = env("PDCHECK_TEST_CRASH_PAIR");
  const long sleep_ms = std::atol(env("PDCHECK_TEST_PAIR_SLEEP_MS").c_str());
  if (!crash_pair.empty() || sleep_ms > 0)
    faults.before_pair_solve = [crash_pair, sleep_ms](const pd::Part& a, const pd::Part& b) {
      if (a.id + ":" + b.id == crash_pair) std::abort();
      if (sleep_ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(sleep_ms));
    };
  const std::string crash_mesh = env("PDCHECK_TEST_CRASH_MESH");
  const std::string hang_mesh = env("PDCHECK_TEST_HANG_MESH");
  if (!crash_mesh.empty() || !hang_mesh.empty())
    faults.before_mesh_load = [crash_mesh, hang_mesh](const std::string& path) {
      if (ends_with(path, crash_mesh)) std::abort();
      if (ends_with(path, hang_mesh))
        for (;;) pause();
    };
  return run_cli(argc, argv, faults);
}
