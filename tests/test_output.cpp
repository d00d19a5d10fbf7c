// Where the report goes: -o PATH whatever the path names, standard output
// whatever happens to it, and bad output options refused before the run.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "shell_run.h"

using namespace pd_test;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

bool no_temporary_files(const std::string& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind(".", 0) == 0 && e.path().filename() != ".stderr")
      return false;
  return true;
}

mode_t mode_of(const std::string& path) {
  struct stat st {};
  lstat(path.c_str(), &st);
  return st.st_mode;
}

}  // namespace

TEST(Output, DeviceIsWrittenThroughNotReplaced) {
  const std::string dir = scratch_dir("out_device");
  // As root, private null and full devices (replacing the machine's would
  // break everything else if this test ever failed); otherwise /dev's.
  std::string null_dev = dir + "/null", full_dev = dir + "/full";
  if (geteuid() != 0 || mknod(null_dev.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0 ||
      mknod(full_dev.c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0) {
    null_dev = "/dev/null";
    full_dev = "/dev/full";
  }
  const ShellRun r = shell(dir, "\"$PDCHECK\" \"$DEMO\" -q -o " + null_dev);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(S_ISCHR(mode_of(null_dev))) << null_dev << " is no longer a device";
  // A full device takes the write and says the disk is full.
  const ShellRun full = shell(dir, "\"$PDCHECK\" \"$DEMO\" -q -o " + full_dev);
  EXPECT_EQ(full.code, 2);
  EXPECT_NE(full.err.find("No space left"), std::string::npos) << full.err;
  EXPECT_TRUE(S_ISCHR(mode_of(full_dev))) << full_dev << " is no longer a device";
  EXPECT_TRUE(no_temporary_files(dir));
}

TEST(Output, FifoIsWrittenThrough) {
  const std::string dir = scratch_dir("out_fifo");
  const ShellRun r =
      shell(dir,
            "mkfifo pipe && { cat pipe > got & } && \"$PDCHECK\" \"$DEMO\" -q -o pipe;"
            // A FIFO replaced by a file would leave the reader waiting for ever.
            " code=$?; [ -p pipe ] || kill $!; wait; exit $code");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(S_ISFIFO(mode_of(dir + "/pipe")));
  EXPECT_EQ(json::parse(read_text(dir + "/got"))["summary"]["interference"], 1);
}

TEST(Output, SymlinkIsFollowed) {
  const std::string dir = scratch_dir("out_symlink");
  const ShellRun r = shell(dir,
                           "mkdir real && echo old > real/report.json && ln -s real/report.json "
                           "link.json && ln -s real/new.json dangling.json &&"
                           " \"$PDCHECK\" \"$DEMO\" -q -o link.json;"
                           " \"$PDCHECK\" \"$DEMO\" -q -o dangling.json");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(S_ISLNK(mode_of(dir + "/link.json")));
  EXPECT_TRUE(S_ISLNK(mode_of(dir + "/dangling.json")));
  EXPECT_EQ(json::parse(read_text(dir + "/real/report.json"))["summary"]["interference"], 1);
  EXPECT_EQ(json::parse(read_text(dir + "/real/new.json"))["summary"]["interference"], 1);
  EXPECT_TRUE(no_temporary_files(dir + "/real"));
}

TEST(Output, NewFileHonoursTheUmaskAndAnOldOneKeepsItsMode) {
  const std::string dir = scratch_dir("out_umask");
  const ShellRun r = shell(dir,
                           "umask 022 && \"$PDCHECK\" \"$DEMO\" -q -o a.json;"
                           " umask 077 && \"$PDCHECK\" \"$DEMO\" -q -o b.json;"
                           " echo old > c.json && chmod 640 c.json && umask 022 &&"
                           " \"$PDCHECK\" \"$DEMO\" -q -o c.json");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(mode_of(dir + "/a.json") & 0777, 0644u);
  EXPECT_EQ(mode_of(dir + "/b.json") & 0777, 0600u);
  EXPECT_EQ(mode_of(dir + "/c.json") & 0777, 0640u);
  EXPECT_EQ(json::parse(read_text(dir + "/c.json"))["summary"]["interference"], 1);
}

TEST(Output, StdoutWriteErrorsAreReported) {
  const std::string dir = scratch_dir("out_stdout");
  const ShellRun full = shell(dir, "\"$PDCHECK\" \"$DEMO\" -q > /dev/full");
  EXPECT_EQ(full.code, 2);
  EXPECT_NE(full.err.find("standard output: No space left"), std::string::npos) << full.err;
  const ShellRun closed = shell(dir, "\"$PDCHECK\" \"$DEMO\" -q >&-");
  EXPECT_EQ(closed.code, 2);
  EXPECT_NE(closed.err.find("standard output: Bad file descriptor"), std::string::npos)
      << closed.err;
  // The reader is gone long before the report (after the run) is written.
  const ShellRun gone =
      shell(dir, "{ \"$PDCHECK\" \"$DEMO\" -q; echo $? > code; } | true; cat code");
  EXPECT_EQ(gone.out, "2\n") << gone.err;
  EXPECT_NE(gone.err.find("standard output: Broken pipe"), std::string::npos) << gone.err;
}

TEST(Output, BadOutputOptionsAreRefused) {
  const std::string dir = scratch_dir("out_refused");
  const ShellRun empty = shell(dir, "\"$PDCHECK\" \"$DEMO\" -q -o \"\"");
  EXPECT_EQ(empty.code, 2);
  EXPECT_TRUE(empty.out.empty());
  EXPECT_NE(empty.err.find("-o : empty path"), std::string::npos) << empty.err;
  const ShellRun is_dir = shell(dir, "\"$PDCHECK\" \"$DEMO\" -q -o .");
  EXPECT_EQ(is_dir.code, 2);
  EXPECT_NE(is_dir.err.find("is a directory"), std::string::npos) << is_dir.err;
  const ShellRun seed = shell(dir, "\"$PDCHECK\" \"$DEMO\" -q --seed -1");
  EXPECT_EQ(seed.code, 2);
  EXPECT_NE(seed.err.find("--seed"), std::string::npos) << seed.err;
  for (const char* t : {"nan", "inf"}) {
    const ShellRun timeout =
        shell(dir, std::string("\"$PDCHECK\" \"$DEMO\" -q --pair-timeout ") + t);
    EXPECT_EQ(timeout.code, 2) << t;
    EXPECT_NE(timeout.err.find("--pair-timeout"), std::string::npos) << timeout.err;
  }
}

TEST(Output, PathIsCheckedBeforeTheRun) {
  // The paper's MLSL settings on the demo take ~10 s with one worker. A bad
  // path must fail at once, not after the run (the bound is loose on purpose).
  const std::string dir = scratch_dir("out_before");
  for (const char* path : {"missing/report.json", "/proc/report.json", "notadir/x.json"}) {
    const auto t0 = std::chrono::steady_clock::now();
    const ShellRun r = shell(dir, std::string("touch notadir; \"$PDCHECK\" \"$DEMO\" -q "
                                              "--jobs 1 --method mlsl-paper -o ") +
                                      path);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(r.code, 2) << path;
    EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
    EXPECT_LT(s, 3.0) << path << ": the run went ahead before the path was checked";
  }
  if (geteuid() != 0) {  // root writes into a read-only directory anyway
    const ShellRun ro =
        shell(dir, "mkdir ro && chmod 555 ro && \"$PDCHECK\" \"$DEMO\" -q -o ro/r.json");
    EXPECT_EQ(ro.code, 2);
    EXPECT_NE(ro.err.find("Permission denied"), std::string::npos) << ro.err;
  }
}
