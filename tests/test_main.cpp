// The tests' main. Every test process writes its scratch files under a fresh
// directory of its own (TEST_TMPDIR, which testing::TempDir() reads, and
// TMPDIR, which the pdcheck processes a test starts inherit), removed when
// every test of the process passed and kept, named on stderr, when one failed.
// Without it each of the ~700 test processes left its files in /tmp (5,700
// entries after a few days of runs on one machine).
#include <gtest/gtest.h>
#include <stdlib.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "brep/occt_backend.h"

int main(int argc, char** argv) {
  // The Open CASCADE code is linked into the tests: in-process calls take it
  // from here, the pdcheck binaries they run load their module.
  pd::use_brep_backend(pd::linked_brep_backend());
  const char* base_env = std::getenv("TMPDIR");
  std::string base = base_env != nullptr && *base_env != '\0' ? base_env : "/tmp";
  std::vector<char> templ(base.begin(), base.end());
  const std::string tail = "/pdcheck-tests-XXXXXX";
  templ.insert(templ.end(), tail.begin(), tail.end());
  templ.push_back('\0');
  const char* made = ::mkdtemp(templ.data());
  std::string root;
  if (made != nullptr) {
    root = made;
    ::setenv("TEST_TMPDIR", (root + "/").c_str(), 1);
    ::setenv("TMPDIR", root.c_str(), 1);
  }
  testing::InitGoogleTest(&argc, argv);
  const int code = RUN_ALL_TESTS();
  if (!root.empty()) {
    if (code == 0) {
      std::error_code ec;
      std::filesystem::remove_all(root, ec);
    } else {
      std::fprintf(stderr, "pdcheck_tests: scratch files kept in %s\n", root.c_str());
    }
  }
  return code;
}
