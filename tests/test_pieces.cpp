// The "pieces" vocabulary (scene/pieces.cpp): one table for the scene parser,
// the CLI and the report, so every name reads back as the mode it names.
#include <gtest/gtest.h>

#include "scene/scene.h"

using namespace pd;

TEST(Pieces, EveryModeReadsBackFromItsName) {
  for (Pieces p : {Pieces::kAuto, Pieces::kHull, Pieces::kMeshes, Pieces::kDecompose}) {
    const std::string name = pieces_name(p);
    EXPECT_NE(name, "?");
    ASSERT_TRUE(parse_pieces(name)) << name;
    EXPECT_EQ(*parse_pieces(name), p) << name;
  }
  EXPECT_STREQ(pieces_name(Pieces::kDecompose), "decompose");  // the documented spelling
  EXPECT_STREQ(pieces_name(Pieces::kMeshes), "meshes");
}

TEST(Pieces, NamesAreExactAndCaseSensitive) {
  for (const char* bad : {"", "Hull", "hulls", " auto", "mesh", "decompose "})
    EXPECT_FALSE(parse_pieces(bad)) << "'" << bad << "'";
}
