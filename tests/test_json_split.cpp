// The top-level array of a scene file (json_split.cpp), split for parallel parsing.
#include <gtest/gtest.h>

#include "scene/json_split.h"

using namespace pd;

TEST(JsonSplit, ElementsOfTheTopLevelArray) {
  const std::string text =
      R"( { "a": {"parts": [1]}, "s": "]\"[", "parts" : [ {"id": "x]\"}"} ,[1,[2]], "q", 3.5e2 ,)"
      R"(null ] , "z": [] } )";
  const auto span = top_level_array(text, "parts");
  ASSERT_TRUE(span);
  std::vector<std::string> got;
  for (const auto& [b, e] : span->elements) got.push_back(text.substr(b, e - b));
  EXPECT_EQ(got,
            (std::vector<std::string>{R"({"id": "x]\"}"})", "[1,[2]]", "\"q\"", "3.5e2", "null"}));
  EXPECT_EQ(text[span->begin], '[');
  EXPECT_EQ(text[span->end - 1], ']');
  EXPECT_TRUE(top_level_array(R"({"parts": []})", "parts")->elements.empty());
  // Not split: the whole-text parse decides (and reports any error).
  for (const char* bad : {R"([1, 2])", R"({"parts": 3})", R"({"parts": [1], "parts": [2]})",
                          R"({"parts": [1, 2)", R"({"parts": [1 2]})", R"({"parts": [1]} x)",
                          R"({"parts": ["1]})", R"({"other": [1]})", R"({})", ""})
    EXPECT_FALSE(top_level_array(bad, "parts")) << bad;
}
