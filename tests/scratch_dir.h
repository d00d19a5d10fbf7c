// Per-test scratch directories and files: each test process writes under its
// own path, so parallel ctest runs never share one. And the message of an
// error a test expects.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

namespace pd_test {

/// This test process's own directory under the test temp dir, created on first
/// use. ctest runs the tests in parallel processes: two of them writing one
/// shared name made one read the other's half-written file (a scene hash that
/// differed between the shards of one run).
inline const std::string& process_dir() {
  static const std::string dir = [] {
    const std::string d = testing::TempDir() + "pdcheck_" + std::to_string(getpid()) + "/";
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

/// The path `group`_`name`_<pid> under the test temp dir, removed: for code that
/// must create its directory itself (the caches).
inline std::filesystem::path absent_dir(const std::string& group, const std::string& name) {
  const std::filesystem::path d = std::filesystem::path(testing::TempDir()) /
                                  (group + "_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(d);
  return d;
}

/// An empty directory `group`_`name`_<pid> under the test temp dir.
inline std::filesystem::path scratch_dir(const std::string& group, const std::string& name) {
  const std::filesystem::path d = absent_dir(group, name);
  std::filesystem::create_directories(d);
  return d;
}

/// A file's whole text ("" when it cannot be read).
inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline void write_bytes(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

/// The message of the E that `f` throws, or "(no error)" when it throws none
/// (any other exception goes on).
template <class E>
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace pd_test
