// The run's warnings on stderr (warning_lines.cpp): a part's own warnings one
// line each, set-up warnings once per kind with a count of the rest.
#include <gtest/gtest.h>

#include "report/warning_lines.h"
#include "report_fixture.h"
#include "scene/setup_warnings.h"

using namespace pd;
using namespace pd::test;

TEST(WarningLines, OwnWarningsEachSetUpWarningsOncePerKind) {
  ReportFixture f;
  const std::string placement = std::string(kNonRigidPlacement) + ": scale 2";
  f.part("a").warnings = {"PLY header line 3 skipped", placement};
  f.part("b").warnings = {placement};
  f.part("c").warnings = {std::string(kNonRigidPlacement) + ": shear"};
  PairResult& p = f.pair(0, 1, Status::kFalsePositive, 0.05);
  p.warnings = {std::string(kToleranceBelowResolution) + ": 1e-09 mm below 1e-06 mm",
                "a pair's own note"};
  const std::vector<std::string> lines = warning_lines(f.run);
  const std::vector<std::string> want = {
      "part \"a\": PLY header line 3 skipped",
      std::string(kNonRigidPlacement) +
          ": part \"a\": scale 2 (and 2 more: the report's warnings list each)",
      std::string(kToleranceBelowResolution) + ": a / b: 1e-09 mm below 1e-06 mm"};
  EXPECT_EQ(lines, want);
}

TEST(WarningLines, PairsOfUnknownPartsAreSkipped) {
  ReportFixture f;
  f.part("a");
  PairResult& p = f.pair(0, 5, Status::kError, 0);  // e.g. a damaged merge input
  p.warnings = {std::string(kToleranceCoversPart) + ": x"};
  EXPECT_TRUE(warning_lines(f.run).empty());
}
