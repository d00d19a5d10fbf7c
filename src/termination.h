// What a termination signal (SIGTERM, SIGINT, SIGHUP) does to a run: it is
// forwarded to the tracked child processes, they are reaped, tracked temporary
// files are removed, and the process exits with 128 + the signal. Without it a
// `kill PID` of the parent alone (systemd, Popen.terminate()) orphans workers
// that go on solving, and can leave half-written temporary files behind.
#pragma once

#include <signal.h>
#include <sys/types.h>

#include <string>

namespace pd {

/// Installs the handlers (the CLI calls it once; a library user may not want it).
void install_termination_handlers();

/// Children the handler must forward a termination signal to and reap.
void track_child(pid_t pid);
void untrack_child(pid_t pid);

/// Blocks the termination signals in this thread while alive. Around fork():
/// a child never runs the parent's handler, and the parent tracks the child
/// before a signal can arrive.
class TerminationBlocked {
 public:
  TerminationBlocked();
  ~TerminationBlocked();
  TerminationBlocked(const TerminationBlocked&) = delete;
  TerminationBlocked& operator=(const TerminationBlocked&) = delete;
  /// In the child of a fork made under this block: default dispositions back, signals unblocked.
  void reset_in_child() const;

 private:
  sigset_t old_;
};

/// A temporary file the handler removes if the process is terminated while it
/// is tracked: from just after its creation (under TerminationBlocked) until
/// it is renamed or removed and this object ends.
class TrackedTempFile {
 public:
  TrackedTempFile() = default;
  void track(const std::string& path);
  ~TrackedTempFile();
  TrackedTempFile(const TrackedTempFile&) = delete;
  TrackedTempFile& operator=(const TrackedTempFile&) = delete;

 private:
  int slot_ = -1;
};

/// A temporary directory of plain files (the run's mesh store) that the
/// handler removes, files and all, if the process is terminated while it is
/// tracked: from just after its creation (under TerminationBlocked) until this
/// object ends. It holds the directory open, to list it without allocating.
class TrackedTempDir {
 public:
  TrackedTempDir() = default;
  void track(const std::string& dir);
  ~TrackedTempDir();
  TrackedTempDir(const TrackedTempDir&) = delete;
  TrackedTempDir& operator=(const TrackedTempDir&) = delete;

 private:
  int slot_ = -1;
};

}  // namespace pd
