// The report against its published schema, and the fields CI keys on.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_support.h"
#include "results/fingerprint.h"

using nlohmann::json;
using namespace pd::test;

TEST(ReportOutputs, DemoReportValidatesAgainstTheSchema) {
  const std::string out = process_dir() + "schema_demo_report.json";
  const CliResult r = pdcheck(kSource + "/testdata/demo/scene.json -q -o " + out);
  ASSERT_EQ(r.code, 1) << r.err;
  bool skip = false;
  const std::string errors = validate_json(kSource + "/docs/report.schema.json", out, skip);
  PD_REQUIRE_TOOL(!skip, "python3-jsonschema");
  EXPECT_EQ(errors, "");
}

TEST(ReportOutputs, EveryPairCarriesItsFingerprint) {
  const CliResult r = pdcheck(kSource + "/testdata/demo/scene.json -q");
  const json rep = json::parse(r.out);
  ASSERT_FALSE(rep["pairs"].empty());
  for (const auto& p : rep["pairs"])
    EXPECT_EQ(p["fingerprint"], pd::pair_fingerprint(p["a"], p["b"])) << p.dump();
  // JSON Lines too, line by line as pairs finish.
  const CliResult l = pdcheck(kSource + "/testdata/demo/scene.json -q --format jsonl");
  std::istringstream lines(l.out);
  std::string line;
  int n = 0;
  while (std::getline(lines, line)) {
    const json j = json::parse(line);
    if (j.contains("summary")) continue;
    EXPECT_EQ(j["fingerprint"], pd::pair_fingerprint(j["a"], j["b"]));
    ++n;
  }
  EXPECT_EQ(n, static_cast<int>(rep["pairs"].size()));
}
