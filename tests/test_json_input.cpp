// Small JSON input files (json_input.cpp): errors name the file and the line
// and column, or the JSON path of the offending value.
#include <gtest/gtest.h>

#include <functional>

#include "report/input_error.h"
#include "report/json_input.h"

using namespace pd;

namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ReportInputError& e) {
    EXPECT_EQ(e.exit_code(), kExitBadInput);
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(JsonInput, InvalidJsonSaysLineAndColumn) {
  EXPECT_EQ(parse_json_input(R"({"a": [1, 2]})", "x.json")["a"][1], 2);
  EXPECT_EQ(error_of([] { parse_json_input("{\n  \"a\": 1,\n  \"b\": ]\n}", "x.json"); }),
            "x.json:3:8: invalid JSON");
  EXPECT_EQ(error_of([] { parse_json_input("", "empty.json"); }), "empty.json:1:1: invalid JSON");
  EXPECT_EQ(error_of([] { read_input_file("/nonexistent/dir/b.json"); }),
            "/nonexistent/dir/b.json: cannot read the file");
}

TEST(JsonInput, TypedAccessNamesThePath) {
  const nlohmann::json doc = nlohmann::json::parse(
      R"({"suppressions": [{"a": "x", "reason": 3}, {"a": "y", "reason": "ok", "typo": 1}]})");
  const JsonAt root{doc, "s.json", "$"};
  EXPECT_EQ(root["suppressions"][size_t(0)]["a"].string(), "x");
  EXPECT_TRUE(root["suppressions"][size_t(1)].has("typo"));
  EXPECT_FALSE(root["suppressions"][size_t(1)].has("owner"));
  EXPECT_EQ(error_of([&] { root["suppressions"][size_t(0)]["reason"].string(); }),
            "s.json: $.suppressions[0].reason: must be a string");
  EXPECT_EQ(error_of([&] { root["suppressions"][size_t(0)]["b"]; }),
            "s.json: $.suppressions[0]: missing required key \"b\"");
  EXPECT_EQ(error_of([&] {
              root["suppressions"][size_t(1)].only_keys({"a", "reason"});
            }),
            "s.json: $.suppressions[1].typo: unknown key");
  EXPECT_EQ(error_of([&] { root["suppressions"].object(); }),
            "s.json: $.suppressions: must be an object");
  EXPECT_EQ(error_of([&] { root["suppressions"][size_t(0)]["a"].number(); }),
            "s.json: $.suppressions[0].a: must be a number");
  EXPECT_EQ(error_of([&] { root.array(); }), "s.json: $: must be an array");
  EXPECT_EQ(root["suppressions"][size_t(0)]["reason"].number(), 3.0);
  root["suppressions"][size_t(1)].only_keys({"a", "reason", "typo"});  // all known: no error
}
