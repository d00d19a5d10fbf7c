// The per-part content hashes (content_hashes.cpp): a part's hash follows its
// mesh file's bytes (file_hash.h), computed once per file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "batch/content_hashes.h"
#include "file_hash.h"
#include "scratch_dir.h"

using namespace pd;
namespace fs = std::filesystem;

namespace {

using pd_test::write_bytes;
void write(const fs::path& p, const std::string& bytes) {
  write_bytes(p, bytes);
}

}  // namespace

TEST(ContentHashes, PartHashesFollowTheFile) {
  const fs::path d = pd_test::scratch_dir("content_hashes", "parts");
  write(d / "m.stl", "one");
  SceneSpec s;
  for (const char* id : {"a", "b"}) {
    PartSpec p;
    p.id = id;
    p.mesh = (d / "m.stl").string();
    s.parts.push_back(p);
  }
  const auto files = mesh_file_hashes(s);
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files.begin()->second, file_content_hash((d / "m.stl").string()));
  const auto before = part_content_hashes(s, files);
  EXPECT_EQ(before, part_content_hashes(s));
  EXPECT_EQ(before[0], before[1]);
  write(d / "m.stl", "two");
  EXPECT_NE(part_content_hashes(s)[0], before[0]);
}
