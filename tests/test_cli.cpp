// The pdcheck binary end to end: exit codes, messages, reports.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_support.h"

using nlohmann::json;

namespace {

using pd::test::kSource;
const std::string kDemo = kSource + "/testdata/demo/scene.json";

using CliRun = pd::test::CliResult;
using pd::test::pdcheck;
using pd::test::write_temp;

std::map<std::string, std::string> statuses(const json& report) {
  std::map<std::string, std::string> s;
  for (const auto& p : report["pairs"])
    s[p["a"].get<std::string>() + ":" + p["b"].get<std::string>()] = p["status"];
  return s;
}

// pdcheck with `args` and its stdout on a pseudo-terminal, as a person runs it
// (stderr to /dev/null); what the terminal got, its "\r\n" read as "\n".
CliRun pdcheck_on_terminal(const std::vector<std::string>& args) {
  CliRun r;
  int master = -1;
  const pid_t pid = forkpty(&master, nullptr, nullptr, nullptr);
  if (pid < 0) return r;
  if (pid == 0) {
    const int null = open("/dev/null", O_RDWR);
    dup2(null, STDERR_FILENO);
    dup2(null, STDIN_FILENO);
    std::vector<char*> argv = {const_cast<char*>(PDCHECK_BINARY)};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  char buf[4096];
  for (ssize_t n; (n = read(master, buf, sizeof buf)) > 0;)  // EIO once the child has gone
    for (ssize_t k = 0; k < n; ++k)
      if (buf[k] != '\r') r.out += buf[k];
  close(master);
  int status = 0;
  waitpid(pid, &status, 0);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

json without_timings(json r) {
  r.erase("seconds");
  r.erase("stage_seconds");
  for (auto& p : r["pairs"]) p.erase("time_ms");
  return r;
}

}  // namespace

TEST(Cli, DemoSceneStatuses) {
  const CliRun r = pdcheck(kDemo + " --quiet");
  ASSERT_EQ(r.code, 1) << r.err;
  const json rep = json::parse(r.out);
  const auto s = statuses(rep);
  EXPECT_EQ(s.at("cover:bracket"), "interference");
  EXPECT_EQ(s.at("base:cover"), "false_positive");
  EXPECT_EQ(s.at("slot:pin"), "false_positive");
  EXPECT_EQ(s.at("base:pin"), "separated");     // face contact
  EXPECT_EQ(s.at("base:spacer"), "separated");  // face contact, inline part in cm
  EXPECT_EQ(rep["summary"]["interference"], 1);
  EXPECT_EQ(rep["summary"]["culled"], 9);
  for (const auto& p : rep["pairs"]) {
    ASSERT_TRUE(p.contains("direction"));
    const double n = std::hypot(p["direction"][0].get<double>(), p["direction"][1].get<double>(),
                                p["direction"][2].get<double>());
    EXPECT_NEAR(n, 1.0, 1e-12);
  }
}

TEST(Cli, ExactMethodAgreesOnTheDemo) {
  const json a = json::parse(pdcheck(kDemo + " -q").out),
             b = json::parse(pdcheck(kDemo + " -q --method exact").out);
  ASSERT_EQ(a["pairs"].size(), b["pairs"].size());
  for (size_t k = 0; k < a["pairs"].size(); ++k) {
    EXPECT_EQ(a["pairs"][k]["status"], b["pairs"][k]["status"]);
    EXPECT_NEAR(a["pairs"][k]["depth"].get<double>(), b["pairs"][k]["depth"].get<double>(), 1e-9);
  }
}

TEST(Cli, JobsDoNotChangeTheReport) {
  const CliRun one = pdcheck(kDemo + " -q --jobs 1"), two = pdcheck(kDemo + " -q --jobs 2");
  EXPECT_EQ(without_timings(json::parse(one.out)), without_timings(json::parse(two.out)));
}

TEST(Cli, JobsDoNotChangeALargerReport) {
  // 90 parts: jittered prisms on a lattice (some overlapping their neighbours)
  // and mesh files under shared transforms (hulled once), so the threaded
  // parse, the threaded hulls and the worker queue all take part.
  json parts = json::array();
  for (int k = 0; k < 90; ++k) {
    const double x = 10.0 * (k % 5), y = 10.0 * (k / 5 % 6), z = 10.0 * (k / 30);
    const double r = 5.0 + 0.7 * ((k * 7) % 5) - 0.2;  // radii 4.8 … 7.6: neighbours may meet
    if (k % 9 == 4) {
      parts.push_back({{"id", "mesh" + std::to_string(k)},
                       {"mesh", kSource + "/testdata/formats/box_binary.stl"},
                       {"transform", {1, 0, 0, x, 0, 1, 0, y, 0, 0, 1, z, 0, 0, 0, 1}}});
      continue;
    }
    json v = json::array();
    const int n = 6 + k % 11;
    for (int i = 0; i < n; ++i) {
      const double t = 2 * M_PI * i / n + 0.1 * k;
      for (double h : {-4.0, 4.0}) v.push_back({x + r * std::cos(t), y + r * std::sin(t), z + h});
    }
    parts.push_back({{"id", "p" + std::to_string(k)}, {"vertices", v}});
  }
  const std::string scene = write_temp("lattice_" + std::to_string(getpid()) + ".json",
                                       json{{"tolerance", 0.5}, {"parts", parts}}.dump());
  const CliRun one = pdcheck(scene + " -q --jobs 1"), three = pdcheck(scene + " -q --jobs 3");
  ASSERT_EQ(one.code, 1) << one.err;
  const json a = json::parse(one.out);
  EXPECT_EQ(without_timings(a), without_timings(json::parse(three.out)));
  // Not a trivial batch: every status but error occurs.
  for (const char* k : {"separated", "false_positive", "interference"})
    EXPECT_GT(a["summary"][k].get<int>(), 0) << k << " " << a["summary"];
}

TEST(Cli, TheProductReadsNoFaultInjection) {
  // Faults are injected by the tests' own executable (tests/pdcheck_faults.cpp)
  // only: the variable that crashes a pair there changes nothing here.
  const pd::test::CliResult r =
      pd::test::shell("PDCHECK_TEST_CRASH_PAIR=base:cover " + std::string(PDCHECK_BINARY) + " " +
                      kDemo + " -q --jobs 2");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(statuses(json::parse(r.out)).at("base:cover"), "false_positive");
}

TEST(Cli, CrashedWorkerCostsOnlyItsPair) {
  const CliRun r = pdcheck(kDemo + " -q --jobs 2", "", "PDCHECK_TEST_CRASH_PAIR=base:cover");
  EXPECT_EQ(r.code, 3) << r.err;
  const json rep = json::parse(r.out);
  const auto s = statuses(rep);
  EXPECT_EQ(s.at("base:cover"), "error");
  EXPECT_EQ(s.at("cover:bracket"), "interference");  // the rest of the batch survived
  EXPECT_EQ(rep["pairs"].size(), 6u);
  for (const auto& p : rep["pairs"])
    if (p["status"] == "error") {
      EXPECT_NE(p["error"].get<std::string>().find("worker crashed"), std::string::npos);
    }
}

TEST(Cli, PairTimeoutKillsTheWorker) {
  const CliRun r = pdcheck(kDemo + " -q --jobs 1 --method mlsl-paper --pair-timeout 0.001");
  EXPECT_EQ(r.code, 3);
  const json rep = json::parse(r.out);
  EXPECT_GT(rep["summary"]["error"].get<int>(), 0);
  EXPECT_NE(r.out.find("timed out"), std::string::npos);
}

TEST(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(pdcheck("").code, 2);
  EXPECT_EQ(pdcheck("--no-such-option x.json").code, 2);
  const CliRun missing = pdcheck("/nonexistent/scene.json");
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("/nonexistent/scene.json"), std::string::npos);
  const std::string no_tol = write_temp("no_tol.json", R"({"parts": []})");
  const CliRun r = pdcheck(no_tol);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no tolerance"), std::string::npos) << r.err;
  const CliRun typo = pdcheck(write_temp("typo.json", R"({"tolerance": 1, "prats": []})"));
  EXPECT_EQ(typo.code, 2);
  EXPECT_NE(typo.err.find("prats: unknown key"), std::string::npos) << typo.err;
  EXPECT_EQ(pdcheck(kDemo + " --method nope").code, 2);
  const CliRun help = pdcheck("--help");
  EXPECT_EQ(help.code, 0);
  EXPECT_NE(help.out.find("Examples:"), std::string::npos);
  EXPECT_EQ(pdcheck("--version").code, 0);
}

TEST(Cli, UnreadableMeshesDoNotLoseTheBatch) {
  const std::string f = kSource + "/testdata/formats/";
  const std::string scene = write_temp(
      "partial.json", R"({"tolerance": 0.1, "parts": [
    {"id": "box", "mesh": ")" +
                          f + R"(box_ascii.stl"},
    {"id": "box2", "mesh": ")" +
                          f + R"(box.obj", "transform": [1,0,0,1.5, 0,1,0,0, 0,0,1,0, 0,0,0,1]},
    {"id": "bad", "mesh": ")" +
                          f + R"(garbage.stl"},
    {"id": "nan", "mesh": ")" +
                          f + R"(nan.obj"},
    {"id": "gone", "mesh": "no/such/file.stl"}]})");
  const CliRun r = pdcheck(scene + " -q");
  EXPECT_EQ(r.code, 3) << r.err;
  const json rep = json::parse(r.out);
  EXPECT_EQ(statuses(rep).at("box:box2"), "interference");  // still checked
  EXPECT_EQ(rep["summary"]["part_errors"], 3);
  for (const auto& p : rep["parts"])
    if (p["id"] != "box" && p["id"] != "box2") {
      EXPECT_TRUE(p.contains("error")) << p.dump();
    }
  EXPECT_NE(r.err.find("part \"gone\""), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no/such/file.stl"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nan.obj: non-finite"), std::string::npos) << r.err;
}

TEST(Cli, PartListOnStdinWithJsonLines) {
  const std::string f = kSource + "/testdata/formats/";
  const CliRun r = pdcheck("- --tolerance 0.5 --units mm --format jsonl -q",
                           "a\t" + f + "box_binary.stl\nb\t" + f + "box_ascii.ply\n");
  EXPECT_EQ(r.code, 1) << r.err;
  std::istringstream lines(r.out);
  std::string first, last, line;
  std::getline(lines, first);
  while (std::getline(lines, line)) last = line;
  EXPECT_EQ(json::parse(first)["status"], "interference");  // identical boxes
  EXPECT_EQ(json::parse(last)["summary"]["interference"], 1);
  // The closing line as docs/report-format.md gives it: part_errors even when none.
  EXPECT_EQ(json::parse(last)["part_errors"], json::array());
  EXPECT_EQ(pdcheck("- -q", "a\t" + f + "box.obj\n").code, 2);  // a part list needs --tolerance
  const CliRun bad = pdcheck("- --tolerance 0.5 --format jsonl -q",
                             "a\t" + f + "box_binary.stl\nb\tno/such.stl\nc\t" + f + "box.obj\n");
  std::istringstream bad_lines(bad.out);
  for (std::string l; std::getline(bad_lines, l);) last = l;
  EXPECT_EQ(json::parse(last)["part_errors"].size(), 1u) << last;
  EXPECT_EQ(json::parse(last)["part_errors"][0]["id"], "b") << last;
}

TEST(Cli, OutputFileIsWrittenWhole) {
  const std::string out = pd_test::process_dir() + "report.json";
  std::remove(out.c_str());
  const CliRun r = pdcheck(kDemo + " -q -o " + out);
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(r.out.empty());
  std::ifstream in(out);
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_EQ(json::parse(ss.str())["summary"]["interference"], 1);
  EXPECT_EQ(pdcheck(kDemo + " -q -o /nonexistent-dir/report.json").code, 2);
}

// Nothing to check is bad input (exit 2), not a green run: an empty part list
// (a failed export upstream), a scene without parts, a scene whose every part
// failed. --allow-empty accepts each.
TEST(Cli, EmptyInputIsAnError) {
  for (const std::string& list : {std::string(), std::string("# no parts tonight\n\n")}) {
    const CliRun r = pdcheck("- --tolerance 0.1 -q", list);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("pdcheck: error: <stdin>: an empty part list"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("--allow-empty"), std::string::npos) << r.err;
    EXPECT_EQ(pdcheck("- --tolerance 0.1 -q --allow-empty", list).code, 0);
  }
  const std::string none = write_temp("no_parts.json", R"({"tolerance": 1, "parts": []})");
  const CliRun r = pdcheck(none + " -q");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("no_parts.json: no parts"), std::string::npos) << r.err;
  EXPECT_EQ(pdcheck(none + " -q --allow-empty").code, 0);

  const std::string failed = write_temp("all_failed.json", R"({"tolerance": 1, "parts": [
      {"id": "a", "mesh": "no/such/a.stl"}, {"id": "b", "mesh": "no/such/b.stl"}]})");
  const CliRun f = pdcheck(failed + " -q");
  EXPECT_EQ(f.code, 2) << f.err;
  EXPECT_NE(f.err.find("every part failed (2 of 2"), std::string::npos) << f.err;
  EXPECT_EQ(json::parse(f.out)["summary"]["part_errors"], 2);  // the report names each
  EXPECT_EQ(json::parse(f.out)["summary"]["exit_code"], 2);
  EXPECT_EQ(pdcheck(failed + " -q --allow-empty").code, 3);  // unchecked parts
  // One usable part is not an empty input.
  const std::string one = write_temp("one_failed.json", R"({"tolerance": 1, "parts": [
      {"id": "a", "vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]]},
      {"id": "b", "mesh": "no/such/b.stl"}]})");
  EXPECT_EQ(pdcheck(one + " -q").code, 3);

  // The merged run of shards whose every part failed is judged as the run.
  const std::string shard = pd_test::process_dir() + "all_failed_shard.json";
  ASSERT_EQ(pdcheck(failed + " -q --shard 1/1 -o " + shard).code, 0);
  const CliRun m = pdcheck("merge " + shard + " -q");
  EXPECT_EQ(m.code, 2) << m.err;
  EXPECT_NE(m.err.find("merge: every part failed"), std::string::npos) << m.err;
  EXPECT_EQ(pdcheck("merge " + shard + " -q --allow-empty").code, 3);
}

// A mesh file given where a scene is expected: the message suggests the part-list form.
TEST(Cli, UsageErrorsSayPdcheckAndSuggestTheNearestOption) {
  const std::string scene = kSource + "/testdata/examples/zhou-m100.json";
  const CliRun typo = pdcheck(scene + " --tolerence 0.1");
  EXPECT_EQ(typo.code, 2);
  EXPECT_EQ(typo.err.rfind("pdcheck: error: ", 0), 0u) << typo.err;
  EXPECT_NE(typo.err.find("did you mean --tolerance (for --tolerence)?"), std::string::npos)
      << typo.err;
  // An option of a subcommand is known too; nothing near: no suggestion.
  EXPECT_NE(pdcheck("merge a.json --outptu x.json").err.find("did you mean --output"),
            std::string::npos);
  const CliRun far = pdcheck(scene + " --zzzzzzzz");
  EXPECT_EQ(far.code, 2);
  EXPECT_EQ(far.err.rfind("pdcheck: error: ", 0), 0u) << far.err;
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
  // A validator's message gets the same prefix.
  const CliRun range = pdcheck(scene + " --load-timeout -3");
  EXPECT_EQ(range.code, 2);
  EXPECT_EQ(range.err.rfind("pdcheck: error: --load-timeout", 0), 0u) << range.err;
}

TEST(Cli, AMeshFileForASceneSuggestsAPartList) {
  const CliRun r = pdcheck(kSource + "/testdata/formats/box_ascii.stl -q");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("box_ascii.stl looks like a mesh file, not a scene: to check mesh files, "
                       "list them on standard input"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("| pdcheck - --tolerance"), std::string::npos) << r.err;
  // A scene that is bad JSON gets no such hint.
  const CliRun j = pdcheck(write_temp("bad.json", "{,}") + " -q");
  EXPECT_EQ(j.code, 2);
  EXPECT_EQ(j.err.find("mesh file"), std::string::npos) << j.err;
}

TEST(Cli, ATerminalGetsATableAndAPipeGetsJson) {
  // Standard output on a terminal, no -o: the verdict and the findings.
  const CliRun table = pdcheck_on_terminal({kDemo, "-q"});
  EXPECT_EQ(table.code, 1) << table.out;
  EXPECT_EQ(table.out.rfind("pdcheck: " + kDemo + ": FAIL: 1 interference (exit code 1)\n", 0), 0u)
      << table.out;
  EXPECT_NE(table.out.find("\ninterference "), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("cover / bracket"), std::string::npos) << table.out;
  EXPECT_EQ(table.out.find('{'), std::string::npos) << table.out;
  // Asked for, JSON on a terminal too; with -o nothing but the file.
  const CliRun asked = pdcheck_on_terminal({kDemo, "-q", "--format", "json"});
  EXPECT_EQ(asked.code, 1);
  EXPECT_TRUE(json::parse(asked.out, nullptr, false).is_object()) << asked.out;
  const std::string file = pd::test::process_dir() + "terminal.json";
  const CliRun to_file = pdcheck_on_terminal({kDemo, "-q", "-o", file});
  EXPECT_EQ(to_file.code, 1);
  EXPECT_EQ(to_file.out, "");
  EXPECT_TRUE(json::parse(pd::test::read_text(file), nullptr, false).is_object());
  // Through a pipe (as every other test here reads it): the JSON report.
  const CliRun piped = pdcheck(kDemo + " -q");
  EXPECT_EQ(piped.code, 1);
  EXPECT_TRUE(json::parse(piped.out, nullptr, false).is_object()) << piped.out;
  // And the table through a pipe when asked for.
  const CliRun piped_table = pdcheck(kDemo + " -q --format table");
  EXPECT_EQ(piped_table.out, table.out);
}
