// One finding as the exports show it (export_finding.cpp): which pairs are
// exported and where each field comes from.
#include <gtest/gtest.h>

#include "report/export_finding.h"
#include "report/suppressions.h"
#include "report_fixture.h"
#include "results/fingerprint.h"

using namespace pd;
using namespace pd::test;

TEST(ExportFinding, EveryPairButASeparatedOneIsExported) {
  EXPECT_FALSE(exported(Status::kSeparated));
  for (const Status s : {Status::kFalsePositive, Status::kInterference, Status::kError,
                         Status::kClearanceViolation, Status::kUndecided})
    EXPECT_TRUE(exported(s)) << status_name(s);
}

TEST(ExportFinding, FieldsFromThePairAndItsReview) {
  ReportFixture f = every_status();
  f.run.pairs[0].at = Vec3(1, 2, 3);
  f.run.pairs[1].tolerance = 0.07;  // tolerance auto: the pair's own band
  const Suppressions sup = parse_suppressions(
      R"({"suppressions": [{"a": "lid <&>", "b": "pin", "reason": "press fit"}]})", "s.json");
  f.options.suppressions = &sup;
  const ReportInput in = f.input();

  const ExportFinding lid = export_finding(in, 0);
  EXPECT_EQ(lid.index, 0u);
  EXPECT_EQ(lid.pair, &f.run.pairs[0]);
  EXPECT_EQ(lid.a, "frame");
  EXPECT_EQ(lid.b, "lid <&>");
  EXPECT_EQ(lid.fingerprint, pair_fingerprint("frame", "lid <&>"));
  EXPECT_EQ(lid.depth, 1.0);
  EXPECT_EQ(lid.margin, 0.1 - 1.0);
  EXPECT_EQ(lid.tolerance, 0.1);
  EXPECT_EQ(lid.at, Vec3(1, 2, 3));
  EXPECT_EQ(lid.group, f.review.groups.groups.at(0).id);
  EXPECT_EQ(lid.suppression, "");
  EXPECT_EQ(lid.baseline_state, "");  // no --baseline
  EXPECT_EQ(lid.message.rfind("frame / lid <&>: interference", 0), 0u) << lid.message;

  const ExportFinding pin = export_finding(in, 1);
  EXPECT_EQ(pin.tolerance, 0.07);
  EXPECT_FALSE(pin.at);
  EXPECT_EQ(pin.group, "");  // a false positive needs no fix

  EXPECT_EQ(export_finding(in, 3).suppression, "press fit");

  const ExportFinding failed = export_finding(in, 5);
  EXPECT_FALSE(failed.depth);  // an error has no depth or margin, not a zero
  EXPECT_FALSE(failed.margin);
  EXPECT_EQ(failed.message, "pin / bolt: error: worker crashed, signal 11");
}
