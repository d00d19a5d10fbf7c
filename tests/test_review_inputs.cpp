// The CI inputs of a run (review_inputs.cpp): files read before any work,
// options that point into them, --fail-on new refused without a baseline.
#include <gtest/gtest.h>

#include <fstream>

#include "bcf_check.h"
#include "report/input_error.h"
#include "report/review_inputs.h"

using namespace pd;
using namespace pd::test;

TEST(ReviewInputs, FilesAreReadAndTheOptionsPointIntoThem) {
  const std::string baseline = process_temp("inputs_baseline.json"),
                    sup = process_temp("inputs_sup.json");
  std::ofstream(baseline)
      << R"({"pairs": [{"a": "x", "b": "y", "status": "interference", "depth": 1}]})";
  std::ofstream(sup) << R"({"suppressions": [{"a": "x", "b": "y", "reason": "press fit"}]})";
  ReviewInputs in;
  load_review_inputs({baseline, sup, "new", true}, 0.25, in);
  ASSERT_TRUE(in.baseline);
  ASSERT_TRUE(in.suppressions);
  EXPECT_EQ(in.options.baseline, &*in.baseline);
  EXPECT_EQ(in.options.suppressions, &*in.suppressions);
  EXPECT_EQ(in.options.fail_on, FailOn::kNew);
  EXPECT_TRUE(in.options.allow_stale);
  EXPECT_EQ(in.options.tolerance, 0.25);
  EXPECT_EQ(in.options.today.size(), 10u);  // YYYY-MM-DD
  EXPECT_EQ(in.suppressions->entries.at(0).reason, "press fit");
  EXPECT_EQ(in.suppressions->path, sup);

  ReviewInputs none;
  load_review_inputs({}, 0.1, none);
  EXPECT_EQ(none.options.baseline, nullptr);
  EXPECT_EQ(none.options.suppressions, nullptr);
  EXPECT_FALSE(none.options.fail_on);  // the run's default bar
}

TEST(ReviewInputs, BadCombinationsAndFilesAreUserErrors) {
  ReviewInputs a;
  try {
    load_review_inputs({"", "", "new", false}, 0.1, a);
    ADD_FAILURE() << "--fail-on new without --baseline was accepted";
  } catch (const ReviewArgsError& e) {
    EXPECT_STREQ(e.what(), "--fail-on new needs --baseline (a previous report)");
    EXPECT_EQ(e.exit_code(), kExitBadInput);
  }
  ReviewInputs b;
  const std::string missing = process_temp("no_such_baseline.json");
  try {
    load_review_inputs({missing, "", "", false}, 0.1, b);
    ADD_FAILURE() << "a missing baseline was accepted";
  } catch (const ReportInputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(missing + ": ", 0), 0u) << e.what();
  }
}
