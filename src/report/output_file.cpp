#include "report/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "atomic_write.h"

namespace fs = std::filesystem;

namespace pd {

namespace {

enum class Kind { kAtomic, kThrough };

struct Resolved {
  Kind kind = Kind::kAtomic;
  std::string target;  ///< the file written: symlinks resolved (kAtomic)
};

[[noreturn]] void fail(const OutputFile& out, const std::string& why) {
  throw OutputError(out.option + " " + out.path + ": " + why);
}

/// The path a dangling symlink chain ends at (the file a shell's `>` would create).
std::string follow_dangling(const OutputFile& out) {
  fs::path p = out.path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p.string();
    std::error_code ec;
    const fs::path next = fs::read_symlink(p, ec);
    if (ec) fail(out, "cannot read the symlink " + p.string() + ": " + ec.message());
    p = next.is_absolute() ? next : p.parent_path() / next;
  }
  fail(out, "too many levels of symbolic links");
}

Resolved resolve(const OutputFile& out) {
  if (out.path.empty()) fail(out, "empty path (leave the option out to write to standard output)");
  struct stat st {};
  if (stat(out.path.c_str(), &st) == 0) {  // follows symlinks
    if (S_ISDIR(st.st_mode)) fail(out, "is a directory");
    if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) || S_ISFIFO(st.st_mode)) {
      if (access(out.path.c_str(), W_OK) != 0) fail(out, std::strerror(errno));
      return {Kind::kThrough, out.path};
    }
    if (!S_ISREG(st.st_mode)) fail(out, "not a regular file, device or FIFO");
    char* real = realpath(out.path.c_str(), nullptr);
    if (!real) fail(out, std::strerror(errno));
    Resolved r{Kind::kAtomic, real};
    std::free(real);
    return r;
  }
  if (errno != ENOENT) fail(out, std::strerror(errno));  // ELOOP, EACCES, ENOTDIR, ...
  const std::string target = follow_dangling(out);
  const fs::path dir = fs::path(target).parent_path();
  struct stat ds {};
  const std::string shown = dir.empty() ? "." : dir.string();
  if (stat(dir.empty() ? "." : dir.c_str(), &ds) != 0)
    fail(out, "directory " + shown + ": " + std::strerror(errno));
  if (!S_ISDIR(ds.st_mode)) fail(out, shown + " is not a directory");
  return {Kind::kAtomic, target};
}

}  // namespace

OutputFile check_output_file(const std::string& option, const std::string& path) {
  const OutputFile out{option, path};
  const Resolved r = resolve(out);
  if (r.kind == Kind::kAtomic) {
    // The one sure test that the rename will work: make a file there.
    std::string dir = fs::path(r.target).parent_path().string(), probe;
    if (dir.empty()) dir = ".";
    const int fd = create_temp_beside(dir, fs::path(r.target).filename().string(), probe);
    if (fd < 0) fail(out, "cannot create a file in " + dir + ": " + std::strerror(errno));
    close(fd);
    unlink(probe.c_str());
  }
  return out;
}

void write_output_file(const OutputFile& out, const std::string& content) {
  const Resolved r = resolve(out);
  if (r.kind == Kind::kAtomic) {
    try {
      write_file_atomically(r.target, content);
    } catch (const OutputError& e) {
      fail(out, e.what());
    }
    return;
  }
  const int fd = open(r.target.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) fail(out, std::strerror(errno));
  bool ok = write_all_fd(fd, content);
  const int err = errno;
  if (close(fd) != 0 && ok) fail(out, std::strerror(errno));
  if (!ok) fail(out, std::strerror(err));
}

void write_stdout(const std::string& content) {
  if (write_all_fd(STDOUT_FILENO, content)) return;
  const int err = errno;
  throw OutputError(std::string("standard output: ") + std::strerror(err) +
                    (err == EPIPE ? " (the reader has gone)" : ""));
}

}  // namespace pd
