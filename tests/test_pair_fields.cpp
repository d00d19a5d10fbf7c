// The one description of a pair result's fields (pair_fields.h): every key
// unique where it is written and described in docs/report.schema.json, which
// the reports are validated against (a field added without its schema entry
// fails here, before any report does).
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <type_traits>

#include "results/pair_fields.h"

using namespace pd;
using nlohmann::json;

namespace {

const json& schema() {
  static const json s =
      json::parse(std::ifstream(std::string(PDCHECK_SOURCE_DIR) + "/docs/report.schema.json"));
  return s;
}

/// (object, key) of every field written, "" for the pair's own object; echoes apart.
template <class T>
void keys_of(const T& t, const std::string& object,
             std::vector<std::pair<std::string, std::string>>& out,
             std::vector<std::string>& echoes) {
  for_each_field(t, [&](const Field& f, const auto& member) {
    using M = std::decay_t<decltype(member)>;
    const std::string where = f.group ? (object.empty() ? "" : object + ".") + f.group : object;
    if (f.echo) {
      echoes.push_back(where + "." + f.key);
      return;
    }
    out.emplace_back(where, f.key);
    const std::string inner = (where.empty() ? "" : where + ".") + f.key;
    if constexpr (std::is_same_v<M, SolveStats>) keys_of(member, inner, out, echoes);
    if constexpr (std::is_same_v<M, std::optional<MotionTrace>>)
      keys_of(MotionTrace{}, inner, out, echoes);
  });
}

/// The schema's properties of a pair entry's object at `path` ("" or "a.b").
const json& properties_at(const std::string& path) {
  const json* p = &schema()["properties"]["pairs"]["items"];
  size_t at = 0;
  while (at < path.size()) {
    const size_t dot = path.find('.', at);
    const std::string part =
        path.substr(at, dot == std::string::npos ? std::string::npos : dot - at);
    p = &(*p)["properties"][part];
    at = dot == std::string::npos ? path.size() : dot + 1;
  }
  return (*p)["properties"];
}

}  // namespace

TEST(PairFields, EveryKeyIsUniqueAndInTheSchema) {
  std::vector<std::pair<std::string, std::string>> keys;
  std::vector<std::string> echoes;
  keys_of(PairResult{}, "", keys, echoes);
  ASSERT_GT(keys.size(), 30u);
  std::set<std::pair<std::string, std::string>> seen;
  for (const auto& [object, key] : keys) {
    EXPECT_TRUE(seen.insert({object, key}).second) << object << "." << key << " twice";
    if (object == "stats" && key == "mlsl_iterations") continue;  // not in the report (when)
    const json& props = properties_at(object);
    ASSERT_TRUE(props.is_object()) << "no schema object for " << object;
    EXPECT_TRUE(props.contains(key))
        << (object.empty() ? "" : object + ".") << key << " is not in docs/report.schema.json";
  }
  // An echo repeats a field written before it (clearance.distance: distance).
  EXPECT_EQ(echoes, std::vector<std::string>{"clearance.distance"});
  EXPECT_TRUE(seen.count({"", "distance"}));
  EXPECT_TRUE(properties_at("clearance").contains("distance"));
  // The pair's identity is the codec's, not a field: never described twice.
  for (const char* own : {"a", "b", "fingerprint"}) EXPECT_FALSE(seen.count({"", own})) << own;
}

TEST(PairFields, ConditionsFollowTheStatus) {
  // An error pair's report shows its error, not an answer; a decided one the reverse.
  auto shown = [](Status s) {
    PairResult r;
    r.status = s;
    std::map<std::string, bool> out;
    for_each_field(r, [&](const Field& f, const auto&) {
      if (!f.group) out[f.key] = f.shown;
    });
    return out;
  };
  const auto error = shown(Status::kError), decided = shown(Status::kInterference);
  EXPECT_TRUE(error.at("error"));
  EXPECT_FALSE(decided.at("error"));
  for (const char* k : {"depth", "direction", "margin", "at", "motion"}) {
    EXPECT_FALSE(error.at(k)) << k;
    EXPECT_TRUE(decided.at(k)) << k;
  }
  for (const char* k : {"status", "method", "stats", "time_ms"}) {
    EXPECT_TRUE(error.at(k)) << k;
    EXPECT_TRUE(decided.at(k)) << k;
  }
}
