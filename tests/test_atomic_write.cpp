// Writing a file whole or not at all (atomic_write.cpp).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>

#include "atomic_write.h"
#include "cli_support.h"
#include "output_error.h"
#include "scratch_dir.h"

using namespace pd;
namespace fs = std::filesystem;

namespace {

size_t entries(const fs::path& d) {
  size_t n = 0;
  for (const auto& e : fs::directory_iterator(d)) n += !e.path().empty();
  return n;
}

}  // namespace

TEST(AtomicWrite, ReplacesWholeKeepsTheModeLeavesNoTemporary) {
  const fs::path d = pd_test::scratch_dir("atomic_write", "whole");
  const std::string path = (d / "r.json").string();
  write_file_atomically(path, "one", false);
  EXPECT_EQ(pd::test::read_text(path), "one");
  ASSERT_EQ(chmod(path.c_str(), 0640), 0);
  write_file_atomically(path, std::string(300000, 'y'));
  EXPECT_EQ(fs::file_size(path), 300000u);
  struct stat st {};
  ASSERT_EQ(stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0640u);
  EXPECT_EQ(entries(d), 1u);
  // A directory that is not there: an OutputError, and nothing created.
  EXPECT_THROW(write_file_atomically((d / "no" / "x").string(), "z"), OutputError);
  EXPECT_EQ(entries(d), 1u);
}

TEST(AtomicWrite, TemporaryFilesAreNewHiddenAndUnique) {
  const fs::path d = pd_test::scratch_dir("atomic_write", "temp");
  std::string a, b;
  const int fa = create_temp_beside(d.string(), "r.json", a);
  const int fb = create_temp_beside(d.string(), "r.json", b);
  ASSERT_GE(fa, 0);
  ASSERT_GE(fb, 0);
  EXPECT_NE(a, b);
  EXPECT_EQ(fs::path(a).parent_path(), d);
  EXPECT_EQ(fs::path(a).filename().string().rfind(".r.json.", 0), 0u) << a;
  EXPECT_TRUE(write_all_fd(fa, std::string(100000, 'q')));
  close(fa);
  close(fb);
  EXPECT_EQ(fs::file_size(a), 100000u);
  EXPECT_EQ(create_temp_beside((d / "missing").string(), "r.json", a), -1);
  EXPECT_FALSE(write_all_fd(-1, "x"));
}
