// A part list on standard input (part_list.cpp): ids, comments, normalised paths.
#include <gtest/gtest.h>

#include <filesystem>

#include "results/fingerprint.h"
#include "scene/scene.h"

using namespace pd;

TEST(PartList, TabSeparatedIdsAndComments) {
  const SceneSpec s =
      parse_part_list("# parts\nwing\tparts/wing.stl\n\nparts/rib.obj\n", "<stdin>");
  ASSERT_EQ(s.parts.size(), 2u);
  EXPECT_EQ(s.parts[0].id, "wing");
  EXPECT_EQ(*s.parts[0].mesh, "parts/wing.stl");
  EXPECT_EQ(s.parts[1].id, "parts/rib.obj");
  EXPECT_THROW(parse_part_list("a\tx.stl\na\ty.stl\n", "<stdin>"), SceneError);
}

TEST(PartList, IdsAreNormalisedPaths) {
  // `find parts`, `find ./parts`, a doubled slash, a detour and the absolute
  // path give the same ids, so the same fingerprints (and baseline findings).
  const std::string cwd = std::filesystem::current_path().string();
  const std::vector<std::string> spellings = {
      "parts/a.stl\nparts/sub/b.stl\n", "./parts/a.stl\n./parts/sub/b.stl\n",
      "parts//a.stl\nparts/sub//b.stl\n", "x/../parts/a.stl\nparts/./sub/../sub/b.stl\n",
      cwd + "/parts/a.stl\n" + cwd + "//parts/sub/b.stl\n"};
  for (const std::string& list : spellings) {
    const SceneSpec s = parse_part_list(list, "<stdin>");
    ASSERT_EQ(s.parts.size(), 2u) << list;
    EXPECT_EQ(s.parts[0].id, "parts/a.stl") << list;
    EXPECT_EQ(s.parts[1].id, "parts/sub/b.stl") << list;
    EXPECT_EQ(pair_fingerprint(s.parts[0].id, s.parts[1].id),
              pair_fingerprint("parts/a.stl", "parts/sub/b.stl"));
  }
  // The file is read as written; ids that stay as they are.
  const SceneSpec s =
      parse_part_list("./parts/a.stl\n../up.stl\n/elsewhere/c.stl\nn\t./m.stl\n", "<stdin>");
  EXPECT_EQ(*s.parts[0].mesh, "./parts/a.stl");
  EXPECT_EQ(s.parts[1].id, "../up.stl");
  if (cwd.rfind("/elsewhere", 0) != 0) {
    EXPECT_EQ(s.parts[2].id, "/elsewhere/c.stl");
  }
  EXPECT_EQ(s.parts[3].id, "n");  // an id given is kept
  EXPECT_EQ(part_list_id("a/.."), ".");
  // One file listed twice under two spellings is one id twice: refused.
  EXPECT_THROW(parse_part_list("parts/a.stl\n./parts/a.stl\n", "<stdin>"), SceneError);
}
