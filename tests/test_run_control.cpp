// A run under signals, a reader that goes away and process limits: workers
// never outlive pdcheck, the exit code says what happened, nothing is left
// behind; and what pdcheck prints cannot be forged by the input.
#include <dirent.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <climits>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>
#include <vector>

#include "shell_run.h"
#include "work_queue.h"

using namespace pd_test;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Live processes whose parent is `parent`, or whose command line contains
/// `needle` (when given), from /proc.
std::vector<pid_t> processes(pid_t parent, const std::string& needle = "") {
  std::vector<pid_t> out;
  DIR* d = opendir("/proc");
  if (!d) return out;
  while (const dirent* e = readdir(d)) {
    const pid_t p = std::atoi(e->d_name);
    if (p <= 0 || p == getpid()) continue;
    const std::string base = std::string("/proc/") + e->d_name;
    std::string stat = read_text(base + "/stat");
    const size_t close = stat.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(stat.substr(close + 2));
    char state = 0;
    pid_t ppid = 0;
    rest >> state >> ppid;
    if (state == 'Z') continue;
    if (needle.empty() ? ppid == parent
                       : read_text(base + "/cmdline").find(needle) != std::string::npos)
      out.push_back(p);
  }
  closedir(d);
  return out;
}

/// Starts pdcheck with `args` in `dir` (stdout and stderr to files there).
/// `tmpdir`, when given, is its TMPDIR.
pid_t start(const std::string& dir, const std::vector<std::string>& args,
            const std::string& env_name = "", const std::string& env_value = "",
            const std::string& tmpdir = "") {
  const pid_t pid = fork();
  if (pid == 0) {
    if (!env_name.empty()) setenv(env_name.c_str(), env_value.c_str(), 1);
    if (!tmpdir.empty()) setenv("TMPDIR", tmpdir.c_str(), 1);
    const int out = open((dir + "/out.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = open((dir + "/err.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(out, 1);
    dup2(err, 2);
    const std::string binary = pdcheck_binary_for(env_name);
    std::vector<char*> argv{const_cast<char*>(binary.c_str())};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(binary.c_str(), argv.data());
    _exit(127);
  }
  return pid;
}

/// A scene of `n` unit cubes, each shifted 0.1 from the last: every pair overlaps.
std::string overlapping_cubes(const std::string& dir, int n) {
  json parts = json::array();
  for (int k = 0; k < n; ++k) {
    json v = json::array();
    for (int c = 0; c < 8; ++c) v.push_back({0.1 * k + (c & 1), (c >> 1) & 1, (c >> 2) & 1});
    parts.push_back({{"id", "cube" + std::to_string(k)}, {"vertices", v}});
  }
  const std::string path = dir + "/cubes.json";
  std::ofstream(path) << json{{"tolerance", 0.01}, {"parts", parts}}.dump();
  return path;
}

}  // namespace

TEST(Signals, TerminationEndsTheWorkersAndLeavesNoFile) {
  for (int sig : {SIGTERM, SIGINT}) {
    const std::string dir = scratch_dir("signal_" + std::to_string(sig));
    // Every pair sleeps 30 s in its worker: the workers are busy when the signal
    // comes. Without a cache the surfaces are in a temporary mesh store, in a
    // TMPDIR of the test's own.
    const std::string tmp = dir + "/tmp";
    fs::create_directories(tmp);
    const pid_t pid =
        start(dir, {kDemo, "-q", "--jobs", "2", "--no-cache", "-o", dir + "/report.json"},
              "PDCHECK_TEST_PAIR_SLEEP_MS", "30000", tmp);
    std::vector<pid_t> workers;
    const auto t0 = std::chrono::steady_clock::now();
    while (since(t0) < 20) {  // the two pair workers (mesh loaders come and go before them)
      std::this_thread::sleep_for(std::chrono::milliseconds(300));
      const auto now = processes(pid);
      if (now.size() == 2 && now == workers) break;
      workers = now;
    }
    ASSERT_EQ(workers.size(), 2u) << "the workers never started";
    kill(pid, sig);  // the parent alone, as kill PID, systemd or Popen.terminate() do
    int status = 0;
    waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 128 + sig)
        << "signal " << sig << ": status " << status;
    for (pid_t w : workers) {
      EXPECT_NE(kill(w, 0), 0) << "worker " << w << " outlived pdcheck";
      kill(w, SIGKILL);  // if it did, do not leave it behind
    }
    for (const auto& e : fs::directory_iterator(dir)) {
      const std::string name = e.path().filename().string();
      EXPECT_TRUE(name == "out.txt" || name == "err.txt" || name == "tmp")
          << name << " left behind";
    }
    for (const auto& e : fs::directory_iterator(tmp))
      ADD_FAILURE() << e.path() << " left behind (the run's mesh store)";
  }
}

TEST(BrokenPipe, JsonLinesStopAtTheFirstFailedWrite) {
  // 28 pairs, each sleeping 1 s in a worker: >= 14 s with 2 workers. The
  // reader leaves after 100 bytes (the first line); the run must stop then.
  const std::string dir = scratch_dir("broken_pipe");
  const std::string scene = overlapping_cubes(dir, 8);
  const auto t0 = std::chrono::steady_clock::now();
  const ShellRun r =
      shell(dir,
            "{ PDCHECK_TEST_PAIR_SLEEP_MS=1000 \"$PDCHECK_FAULTS\" cubes.json -q --jobs 2 "
            "--format jsonl; echo $? > code; } | head -c 100 > head.txt");
  const double seconds = since(t0);
  EXPECT_EQ(read_text(dir + "/code"), "2\n") << r.err;
  EXPECT_NE(r.err.find("standard output: Broken pipe"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the run stopped"), std::string::npos) << r.err;
  EXPECT_LT(seconds, 8.0) << "the run went on after the reader had gone";
  EXPECT_EQ(read_text(dir + "/head.txt").size(), 100u);
  const auto left = processes(0, scene);
  EXPECT_TRUE(left.empty()) << left.size() << " workers left";
  for (pid_t p : left) kill(p, SIGKILL);
}

TEST(Limits, JobsAboveTheOpenFileLimitRunWithFewerWorkers) {
  const std::string dir = scratch_dir("fd_limit");
  overlapping_cubes(dir, 8);
  // Hard limit 48: 28 workers (56 pipe ends) cannot fit; fewer run, and it says so.
  const ShellRun hard =
      shell(dir, "ulimit -n 48 && \"$PDCHECK\" cubes.json --jobs 28 -o hard.json");
  EXPECT_EQ(hard.code, 1) << hard.err;
  EXPECT_NE(hard.err.find("(ulimit -n): running"), std::string::npos) << hard.err;
  EXPECT_EQ(json::parse(read_text(dir + "/hard.json"))["pairs"].size(), 28u);
  // Soft limit 48 under a higher hard one: raised, all workers run, nothing to say.
  const ShellRun soft =
      shell(dir, "ulimit -S -n 48 && \"$PDCHECK\" cubes.json --jobs 28 -o soft.json");
  EXPECT_EQ(soft.code, 1) << soft.err;
  EXPECT_EQ(soft.err.find("ulimit"), std::string::npos) << soft.err;
  EXPECT_EQ(json::parse(read_text(dir + "/soft.json"))["pairs"].size(), 28u);
}

TEST(Limits, PollTimeoutNeverOverflows) {
  EXPECT_EQ(pd::poll_timeout_ms(0.5), 501);
  EXPECT_EQ(pd::poll_timeout_ms(-1.0), 0);
  EXPECT_EQ(pd::poll_timeout_ms(2147484.0), INT_MAX);  // 1000 x this overflows an int
  EXPECT_EQ(pd::poll_timeout_ms(1e300), INT_MAX);
  EXPECT_GT(pd::poll_timeout_ms(2147483.0), 2147480000);
}

TEST(Limits, AHugePairTimeoutDoesNotBusyPoll) {
  // Two 0.5 s tasks under a 3e6 s timeout: the parent must sleep in poll(),
  // not spin (a busy poll burns ~1 s of CPU here; the bound is loose).
  auto cpu = [] {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  };
  const double before = cpu();
  int done = 0;
  pd::run_work_queue(
      {0, 1}, {1, 3e6, {}},
      [](size_t) {
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
        return std::string("x");
      },
      [&](size_t, bool ok, const std::string&) { done += ok; });
  EXPECT_EQ(done, 2);
  EXPECT_LT(cpu() - before, 0.3);
}

TEST(Printable, PartIdsCannotForgeLogLines) {
  const std::string dir = scratch_dir("forged_ids");
  const std::string id = "x\npdcheck: error: forged\x1b[31m";
  std::ofstream(dir + "/scene.json")
      << json{{"tolerance", 0.1},
              {"parts",
               {{{"id", id}, {"mesh", "no/such/file.stl"}},
                {{"id", "ok"}, {"vertices", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}}}}}
             .dump();
  std::ofstream(dir + "/dup.json")
      << json{{"tolerance", 0.1},
              {"parts", {{{"id", id}, {"mesh", "a.stl"}}, {{"id", id}, {"mesh", "b.stl"}}}}}
             .dump();
  for (const char* scene : {"scene.json", "dup.json"}) {
    const ShellRun r = shell(dir, std::string("\"$PDCHECK\" ") + scene + " -o r.json");
    EXPECT_TRUE(r.code == 2 || r.code == 3) << scene << ": " << r.code << " " << r.err;
    EXPECT_NE(r.err.find("x\\npdcheck: error: forged\\e[31m"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("\npdcheck: error: forged"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
  }
}
