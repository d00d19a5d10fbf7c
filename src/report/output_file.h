// An output named on the command line (-o PATH, and every other report file):
// checked before the run, so a bad path fails in a second, not after hours of
// solving; written after it, whole or not at all.
//
//   const pd::OutputFile out = pd::check_output_file("-o", path);  // before the run
//   ...
//   pd::write_output_file(out, text);                              // after it
//
// What the path names decides how it is written:
//   nothing yet, or a regular file  atomically: a temporary file beside it, then rename;
//                                   a new file gets 0666 less the umask, an existing
//                                   one keeps its mode
//   a symlink                       followed: its target is written (or created), the
//                                   link stays
//   a character or block device,    written through in place (-o /dev/null stays a
//   a FIFO                          device, also as root); a FIFO waits for its reader
//   a directory, a socket, a loop   refused
// Both calls throw OutputError, whose message names the option, the path and why.
#pragma once

#include <string>

#include "output_error.h"

namespace pd {

struct OutputFile {
  std::string option;  ///< as the user wrote it ("-o", "--junit"): for messages
  std::string path;    ///< as given
};

/// Checks that `path` can be written: refuses an empty path, a directory, a
/// missing or unwritable directory (by creating and removing a temporary file
/// in it), an unwritable device. Throws OutputError.
OutputFile check_output_file(const std::string& option, const std::string& path);

/// Writes `content` as the table above says, resolving the path again (it may
/// have changed during the run). Throws OutputError.
void write_output_file(const OutputFile& out, const std::string& content);

/// Writes `content` to standard output with every error detected (a full disk,
/// a closed descriptor, a reader gone: EPIPE, with SIGPIPE ignored). Throws
/// OutputError.
void write_stdout(const std::string& content);

}  // namespace pd
