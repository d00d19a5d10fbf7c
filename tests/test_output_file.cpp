// An output named on the command line (output_file.cpp) in process: refused
// before the work when it cannot be written, written whole after it, a
// symlink followed, an old file's mode kept. Through the binary (devices,
// FIFOs, standard output): test_output.cpp.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>

#include "cli_support.h"
#include "output_error.h"
#include "report/output_file.h"

using namespace pd;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d =
      fs::path(testing::TempDir()) / ("output_file_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string error_of(const std::string& option, const std::string& path) {
  try {
    check_output_file(option, path);
  } catch (const OutputError& e) {
    EXPECT_EQ(e.exit_code(), kExitBadInput);
    return e.what();
  }
  return "(no error)";
}

bool only(const fs::path& dir, std::vector<std::string> names) {
  std::vector<std::string> got;
  for (const auto& e : fs::directory_iterator(dir)) got.push_back(e.path().filename().string());
  std::sort(got.begin(), got.end());
  std::sort(names.begin(), names.end());
  return got == names;
}

}  // namespace

TEST(OutputFile, UnwritablePathsAreRefusedNamingOptionAndPath) {
  const fs::path d = fresh_dir("refused");
  const std::string dir = d.string(), missing = (d / "no" / "r.json").string();
  EXPECT_NE(error_of("--junit", dir).find("--junit " + dir), std::string::npos);
  EXPECT_NE(error_of("-o", missing).find("-o " + missing), std::string::npos);
  EXPECT_NE(error_of("--sarif", ""), "(no error)");
  EXPECT_TRUE(only(d, {}));  // checking leaves nothing behind
  const OutputFile ok = check_output_file("-o", (d / "r.json").string());
  EXPECT_EQ(ok.option, "-o");
  EXPECT_FALSE(fs::exists(d / "r.json"));  // checked, not created
}

TEST(OutputFile, WrittenWholeKeepingAnOldFilesMode) {
  const fs::path d = fresh_dir("whole");
  const std::string path = (d / "r.json").string();
  const OutputFile out = check_output_file("-o", path);
  write_output_file(out, "first\n");
  EXPECT_EQ(pd::test::read_text(path), "first\n");
  ASSERT_EQ(chmod(path.c_str(), 0600), 0);
  write_output_file(out, std::string(1 << 20, 'x'));
  EXPECT_EQ(fs::file_size(path), 1u << 20);
  struct stat st {};
  ASSERT_EQ(stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  EXPECT_TRUE(only(d, {"r.json"}));  // no temporary file left
}

TEST(OutputFile, ASymlinkIsFollowedAndStays) {
  const fs::path d = fresh_dir("link");
  fs::create_directories(d / "real");
  fs::create_symlink(d / "real" / "target.json", d / "link.json");
  write_output_file(check_output_file("--sarif", (d / "link.json").string()), "via link");
  EXPECT_TRUE(fs::is_symlink(d / "link.json"));
  EXPECT_EQ(pd::test::read_text((d / "real" / "target.json").string()), "via link");
}
