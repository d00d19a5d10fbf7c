// The one description of a part result's fields (part_fields.h): every key
// unique where it is written and described in docs/report.schema.json.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "results/part_fields.h"

using namespace pd;
using nlohmann::json;

TEST(PartFields, EveryKeyIsUniqueAndInTheSchema) {
  const json schema =
      json::parse(std::ifstream(std::string(PDCHECK_SOURCE_DIR) + "/docs/report.schema.json"));
  const json& part = schema["properties"]["parts"]["items"];
  std::set<std::string> seen;
  const PartResult described{};
  for_each_field(described, [&](const Field& f, const auto&) {
    const std::string where = f.group ? std::string(f.group) + "." + f.key : f.key;
    EXPECT_TRUE(seen.insert(where).second) << where << " twice";
    const json& props = f.group ? part["properties"][f.group]["properties"] : part["properties"];
    EXPECT_TRUE(props.is_object() && props.contains(f.key))
        << where << " is not in docs/report.schema.json";
  });
  EXPECT_GT(seen.size(), 15u);
  // Every key the schema requires is described.
  for (const json& k : part["required"]) EXPECT_TRUE(seen.count(k.get<std::string>())) << k;
}
