// The termination handler (termination.h) in a forked copy of this process:
// a tracked child is signalled and reaped, a tracked temporary file removed,
// the exit status 128 + the signal; a file no longer tracked (renamed into
// place) stays. (Through the binary: Signals.TerminationEndsTheWorkers... in
// test_run_control.)
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

#include "shell_run.h"
#include "termination.h"

using namespace pd_test;
namespace fs = std::filesystem;

TEST(Signals, TheHandlerReapsTrackedChildrenAndRemovesTrackedFiles) {
  // The handler itself, on a temporary file as the atomic writer tracks it.
  const std::string dir = scratch_dir("signal_handler");
  const std::string tmp = dir + "/.report.json.abcdef";
  int report[2];
  ASSERT_EQ(pipe(report), 0);
  const pid_t pid = fork();
  if (pid == 0) {
    pd::install_termination_handlers();
    pid_t child;
    {
      const pd::TerminationBlocked blocked;
      child = fork();
      if (child == 0) {
        blocked.reset_in_child();
        for (;;) pause();
      }
      pd::track_child(child);
    }
    if (write(report[1], &child, sizeof child) != sizeof child) _exit(1);
    close(open(tmp.c_str(), O_WRONLY | O_CREAT, 0644));
    pd::TrackedTempFile tracked;
    tracked.track(tmp);
    raise(SIGTERM);
    _exit(0);
  }
  close(report[1]);
  pid_t child = -1;
  ASSERT_EQ(read(report[0], &child, sizeof child), static_cast<ssize_t>(sizeof child));
  close(report[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGTERM) << status;
  EXPECT_NE(kill(child, 0), 0) << "the tracked child outlived its parent";
  kill(child, SIGKILL);
  EXPECT_FALSE(fs::exists(tmp));
}

TEST(Signals, AFileNoLongerTrackedStays) {
  // The atomic writer's temporary file renamed into place: its tracking ended
  // with the rename, so a later signal must not remove the finished output.
  const std::string dir = scratch_dir("signal_untracked");
  const std::string kept = dir + "/report.json";
  const pid_t pid = fork();
  if (pid == 0) {
    pd::install_termination_handlers();
    {
      pd::TrackedTempFile tracked;
      const std::string tmp = dir + "/.report.json.abcdef";
      close(open(tmp.c_str(), O_WRONLY | O_CREAT, 0644));
      tracked.track(tmp);
      if (rename(tmp.c_str(), kept.c_str()) != 0) _exit(1);
    }
    raise(SIGINT);
    _exit(0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGINT) << status;
  EXPECT_TRUE(fs::exists(kept));
}
