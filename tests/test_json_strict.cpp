// Scene text that the JSON library reads silently or throws on without a
// position (issue 11): duplicate keys, numbers beyond the double range,
// escaped keys. Every error names the file, the place and the JSON path, the
// same with one parsing thread or several.
#include <gtest/gtest.h>

#include "scene/json_split.h"
#include "scene/json_strict.h"
#include "scene/scene.h"

using namespace pd;

namespace {

// The error a scene gives, the same with 1 and 4 parsing threads (or a note
// that says how they differ).
std::string error_of(const std::string& text) {
  std::string what[2];
  for (int t : {0, 1}) try {
      parse_scene_json(text, "s.json", "", std::nullopt, t ? 4 : 1);
      what[t] = "no error";
    } catch (const SceneError& e) {
      what[t] = e.what();
    }
  return what[0] == what[1] ? what[0] : "threads differ: " + what[0] + " | " + what[1];
}

std::string part(const std::string& id, double x = 0) {
  const std::string s = std::to_string(x);
  return R"({"id": ")" + id + R"(", "vertices": [[)" + s + ",0,0],[" + s + "1,0,0],[" + s +
         ",1,0],[" + s + ",0,1]]}";
}

}  // namespace

TEST(StrictJson, NumbersBeyondTheDoubleRangeNameTheirPlace) {
  EXPECT_EQ(error_of(R"({"tolerance": 1e999, "parts": []})"),
            "s.json: invalid JSON at line 1, column 19: tolerance: number 1e999 is outside the "
            "double range (about ±1.8e308)");
  EXPECT_EQ(error_of("{\"tolerance\": 1, \"parts\": [" + part("a") + ",\n" +
                     R"({"id": "b", "vertices": [[0,0,0],[1,0,-2e308]]}]})"),
            "s.json: invalid JSON at line 2, column 44: parts[1].vertices[1][2]: number -2e308 is "
            "outside the double range (about ±1.8e308)");
  // Underflow is not an error: 1e-999 reads as 0, as in every JSON reader.
  EXPECT_EQ(error_of(R"({"tolerance": 1e-999, "parts": []})"), "s.json: tolerance: must be > 0");
}

TEST(StrictJson, DuplicateKeysAreRefusedWithTheirPath) {
  EXPECT_EQ(error_of("{\"tolerance\": 1, \"parts\": [" + part("a") + ", " + part("b") +
                     R"(, {"id": "c", "id": "d", "vertices": [[0,0,0]]}]})"),
            "s.json: parts[2].id: duplicate key \"id\" in one object (JSON readers disagree on "
            "which counts)");
  EXPECT_EQ(error_of(R"({"tolerance": 1, "tolerance": 2, "parts": []})"),
            "s.json: tolerance: duplicate key \"tolerance\" in one object (JSON readers disagree "
            "on which counts)");
  // The same key spelled with an escape is the same key.
  EXPECT_EQ(error_of("{\"tolerance\": 1, \"parts\": [" + part("a") + ", " + part("b") +
                     "], \"par\\u0074s\": [" + part("c") + ", " + part("d", 5) + "]}"),
            "s.json: parts: duplicate key \"parts\" in one object (JSON readers disagree on which "
            "counts)");
  // Keys may repeat in different objects.
  EXPECT_EQ(error_of("{\"tolerance\": 1, \"parts\": [" + part("a") + ", " + part("b") + "]}"),
            "no error");
}

TEST(StrictJson, AnEscapedPartsKeyReadsTheSameWithAnyThreads) {
  const std::string text = "{\"tolerance\": 1, \"par\\u0074s\": [" + part("a") + ", " + part("b") +
                           ", " + part("c", 5) + "]}";
  EXPECT_FALSE(top_level_array(text, "parts"));  // the splitter leaves it to the full parse
  for (int threads : {1, 4}) {
    const SceneSpec s = parse_scene_json(text, "s.json", "", std::nullopt, threads);
    ASSERT_EQ(s.parts.size(), 3u) << threads;
    EXPECT_EQ(s.parts[2].id, "c");
  }
}

TEST(StrictJson, PathsCountArrayElementsAndKeys) {
  try {
    parse_json_strict(R"({"a": [1, {"b": [2, "x", 1e400]}], "c": 0})");
    FAIL() << "no error";
  } catch (const JsonTextError& e) {
    EXPECT_EQ(e.path, "a[1].b[2]");
    EXPECT_EQ(e.byte, 30u);  // the last character of the number
  }
  try {
    parse_json_strict(R"([{"k": 1}, {"k": 1, "j": {"k": 2, "k": 3}}])");
    FAIL() << "no error";
  } catch (const JsonTextError& e) {
    EXPECT_EQ(e.path, "[1].j.k");
  }
  EXPECT_THROW(parse_json_strict("{\"a\": [1, 2}"), JsonTextError);
  EXPECT_EQ(parse_json_strict(R"({"a": [1, {"b": -0.5}], "b": null})")["a"][1]["b"], -0.5);
}
