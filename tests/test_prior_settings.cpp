// An earlier report's unit and settings against the run's (prior_settings.cpp):
// another unit is refused, other settings are warnings.
#include <gtest/gtest.h>

#include "report/input_error.h"
#include "report/prior_settings.h"
#include "report/report_json.h"

using namespace pd;

namespace {

ReportContext run_context() {
  ReportContext c;
  c.units = "mm";
  c.tolerance = 0.1;
  return c;
}

}  // namespace

TEST(PriorSettings, ReadFromAReportDocument) {
  const nlohmann::json doc = nlohmann::json::parse(
      R"({"units": "in", "tolerance": 0.01, "method": {"name": "exact", "seed": 1},
          "hashes": {"scene": "s"}})");
  const PriorSettings p = prior_settings_of(doc);
  EXPECT_EQ(p.units, "in");
  EXPECT_EQ(p.tolerance, 0.01);
  ASSERT_TRUE(p.method);
  EXPECT_EQ((*p.method)["name"], "exact");
  EXPECT_EQ(p.rules_hash, "");  // hashes without rules: no rules
  const PriorSettings none = prior_settings_of(nlohmann::json::parse(R"({"units": 3})"));
  EXPECT_FALSE(none.units);
  EXPECT_FALSE(none.tolerance);
  EXPECT_FALSE(none.method);
  EXPECT_FALSE(none.rules_hash);  // no hashes: nothing to compare
  EXPECT_FALSE(prior_settings_of(nlohmann::json::array()).units);
}

TEST(PriorSettings, AnotherUnitIsRefusedNamingBoth) {
  PriorSettings p;
  p.units = "in";
  try {
    check_prior_settings("--baseline", "old.json", p, run_context());
    ADD_FAILURE() << "another unit was accepted";
  } catch (const ReportInputError& e) {
    EXPECT_EQ(
        std::string(e.what()).rfind("--baseline old.json: the report is in in, this run in mm", 0),
        0u)
        << e.what();
    EXPECT_EQ(e.exit_code(), kExitBadInput);
  }
}

TEST(PriorSettings, OtherSettingsAreWarningsEachNamed) {
  const ReportContext run = run_context();
  PriorSettings same;
  same.units = "mm";
  same.tolerance = 0.1;
  same.method = nlohmann::json::parse(method_json(run.solver).dump());
  same.rules_hash = "";
  EXPECT_TRUE(check_prior_settings("--reuse", "r.json", same, run).empty());

  PriorSettings other = same;
  other.tolerance = 0.2;
  other.method = nlohmann::json{{"name", "grid"}, {"seed", 1}, {"grid", 40}};
  other.rules_hash = "abc";
  const std::vector<std::string> w = check_prior_settings("--reuse", "r.json", other, run);
  ASSERT_EQ(w.size(), 3u);
  EXPECT_EQ(w[0].rfind("--reuse r.json: written with tolerance 0.2 mm, this run's is 0.1 mm", 0),
            0u)
      << w[0];
  EXPECT_EQ(w[1].rfind("--reuse r.json: written with method {", 0), 0u) << w[1];
  EXPECT_NE(w[2].find("under other rules (hashes.rules abc), this run has none"), std::string::npos)
      << w[2];
  // Key order in the method block does not count.
  PriorSettings reordered = same;
  nlohmann::json m = nlohmann::json::object();
  const nlohmann::json now = *same.method;
  for (auto it = now.items().begin(); it != now.items().end(); ++it) m[it.key()] = it.value();
  reordered.method = m;
  EXPECT_TRUE(check_prior_settings("--reuse", "r.json", reordered, run).empty());
}

TEST(PriorSettings, ToleranceAutoIsSaidAsAuto) {
  const PriorSettings p = prior_settings_of(nlohmann::json::parse(R"({"tolerance": "auto"})"));
  EXPECT_TRUE(p.auto_tolerance);
  EXPECT_FALSE(p.tolerance);
  const std::vector<std::string> w = check_prior_settings("--baseline", "b.json", p, run_context());
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].rfind("--baseline b.json: written with tolerance auto, this run's is 0.1 mm", 0),
            0u)
      << w[0];
  ReportContext under_auto = run_context();
  under_auto.auto_tolerance = AutoTolerance{};
  under_auto.tolerance = 0.0;
  EXPECT_TRUE(check_prior_settings("--baseline", "b.json", p, under_auto).empty());
  PriorSettings fixed;
  fixed.tolerance = 0.1;
  ASSERT_EQ(check_prior_settings("--reuse", "r.json", fixed, under_auto).size(), 1u);
  EXPECT_NE(check_prior_settings("--reuse", "r.json", fixed, under_auto)[0].find(
                "written with tolerance 0.1 mm, this run's is auto"),
            std::string::npos);
}
