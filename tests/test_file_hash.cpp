// The one file hash (file_hash.cpp): a regular file hashes its bytes; anything
// else never matches a readable file (a directory is not an empty file). The
// per-part hashes built on it: test_content_hashes.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "file_hash.h"
#include "hash.h"
#include "scratch_dir.h"

using namespace pd;
namespace fs = std::filesystem;

namespace {

using pd_test::write_bytes;
void write(const fs::path& p, const std::string& bytes) {
  write_bytes(p, bytes);
}

}  // namespace

TEST(FileHash, RegularFileIsItsBytes) {
  const fs::path d = pd_test::scratch_dir("file_hash", "bytes");
  const std::string bytes("solid x\n\0\x01\xff end", 16);
  write(d / "a.stl", bytes);
  EXPECT_EQ(file_content_hash((d / "a.stl").string()), content_hash(bytes));
  write(d / "empty.stl", "");
  EXPECT_EQ(file_content_hash((d / "empty.stl").string()), content_hash(""));
}

TEST(FileHash, NonFilesNeverMatchAReadableFile) {
  const fs::path d = pd_test::scratch_dir("file_hash", "nonfiles");
  write(d / "empty.stl", "");
  const std::string empty = file_content_hash((d / "empty.stl").string());
  fs::create_directory(d / "dir.stl");
  const std::string dir = file_content_hash((d / "dir.stl").string());
  const std::string missing = file_content_hash((d / "missing.stl").string());
  EXPECT_NE(dir, empty);
  EXPECT_NE(missing, empty);
  EXPECT_NE(dir, missing);  // the path and the reason are in the hash
}

// A part's hash follows its file's bytes, read once per file however many
// parts use it (the map), and the map agrees with reading the file again.
