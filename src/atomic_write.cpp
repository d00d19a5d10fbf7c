#include "atomic_write.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>

#include "output_error.h"
#include "termination.h"

namespace pd {

bool write_all_fd(int fd, const std::string& content) {
  size_t off = 0;
  while (off < content.size()) {
    const ssize_t w = ::write(fd, content.data() + off, content.size() - off);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) {
      if (w == 0) errno = EIO;
      return false;
    }
    off += static_cast<size_t>(w);
  }
  return true;
}

int create_temp_beside(const std::string& dir, const std::string& stem, std::string& created) {
  static const char kChars[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  std::random_device rd;
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string name = "." + stem + ".";
    for (int k = 0; k < 6; ++k) name += kChars[rd() % (sizeof kChars - 1)];
    created = (std::filesystem::path(dir) / name).string();
    // Mode 0666 through open(): the kernel applies the umask (mkstemp's 0600 would not).
    const int fd = open(created.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  errno = EEXIST;
  return -1;
}

void write_file_atomically(const std::string& path, const std::string& content, bool sync) {
  const std::filesystem::path target(path);
  std::string dir = target.parent_path().string();
  if (dir.empty()) dir = ".";
  struct stat old {};
  const bool replacing = stat(path.c_str(), &old) == 0 && S_ISREG(old.st_mode);

  std::string tmp;
  TrackedTempFile tracked;  // a termination signal removes the file while tracked
  int fd = -1;
  {
    const TerminationBlocked blocked;  // no signal between creating and tracking it
    fd = create_temp_beside(dir, target.filename().string(), tmp);
    if (fd >= 0) tracked.track(tmp);
  }
  if (fd < 0)
    throw OutputError(path + ": cannot create a temporary file in " + dir + ": " +
                      std::strerror(errno));
  bool ok = write_all_fd(fd, content);
  if (ok && replacing) {
    ok = fchmod(fd, old.st_mode & 07777) == 0;
    if (ok && geteuid() == 0) ok = fchown(fd, old.st_uid, old.st_gid) == 0;
  }
  ok = ok && (!sync || fsync(fd) == 0);
  int err = ok ? 0 : errno;
  if (close(fd) != 0 && ok) {
    ok = false;
    err = errno;
  }
  if (ok && std::rename(tmp.c_str(), path.c_str()) != 0) {
    ok = false;
    err = errno;
  }
  if (!ok) {
    unlink(tmp.c_str());
    throw OutputError(path + ": cannot write: " + std::strerror(err));
  }
}

}  // namespace pd
