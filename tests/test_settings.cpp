// Depth methods and their settings (settings.h, methods.cpp): names both ways,
// and the one list of settings every hash and the report follow.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <type_traits>

#include "solve/methods.h"
#include "solve/settings.h"

using namespace pd;

TEST(Settings, MethodNamesRoundTrip) {
  std::set<std::string> names;
  for (const Method m :
       {Method::kMlsl, Method::kMlslPaper, Method::kGsLocal, Method::kGrid, Method::kExact}) {
    const std::string n = method_name(m);
    EXPECT_TRUE(names.insert(n).second) << n;
    EXPECT_EQ(parse_method(n), m) << n;
  }
  EXPECT_EQ(names, (std::set<std::string>{"mlsl", "mlsl-paper", "gs-local", "grid", "exact"}));
  EXPECT_FALSE(parse_method("MLSL"));
  EXPECT_FALSE(parse_method(""));
}

TEST(Settings, EachSettingVisitedOnceWithItsOwnMember) {
  SolverSettings s;
  std::set<std::string> keys;
  std::set<const void*> members;
  for_each_setting(s, [&](const Setting& setting, auto& member) {
    EXPECT_TRUE(keys.insert(setting.key).second) << setting.key;
    EXPECT_TRUE(members.insert(&member).second) << setting.key << " shares a member";
    // Mutable: a reader can set every setting through it.
    using M = std::remove_reference_t<decltype(member)>;
    static_assert(!std::is_const_v<M>);
  });
  EXPECT_EQ(keys.size(), 15u);
  EXPECT_FALSE(keys.count("epa"));  // the one setting outside the list (settings.h says why)
  // A setting shown in no method's block has no report key, and the reverse.
  for_each_setting(s, [&](const Setting& setting, const auto&) {
    EXPECT_EQ(setting.report_key != nullptr, setting.methods != 0) << setting.key;
  });
  const Setting grid{"grid", "grid", 1u << static_cast<unsigned>(Method::kGrid)};
  EXPECT_TRUE(grid.reported_for(Method::kGrid));
  EXPECT_FALSE(grid.reported_for(Method::kMlsl));
  EXPECT_FALSE(Setting{"max_seconds"}.reported_for(Method::kMlsl));
}
