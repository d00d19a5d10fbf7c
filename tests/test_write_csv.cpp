// The CSV export (--csv, write_csv.cpp) in process: a row per pair that is not
// separated, parsed back by a strict RFC 4180 reader (tests/csv_reader.h).
// Through the binary, against the JSON report: test_exports.cpp.
#include <gtest/gtest.h>

#include "csv_reader.h"
#include "report_fixture.h"
#include "results/fingerprint.h"

using namespace pd::test;

// In process: a hand-made run whose ids need quoting, rows parsed back.
TEST(WriteCsv, QuotesIdsAsRfc4180Says) {
  ReportFixture f;
  for (const std::string id : {"plain", "comma, id", "quote \"q\"", "line\nbreak", "far"})
    f.part(id);
  f.pair(0, 1, pd::Status::kInterference, 0.3);
  f.pair(1, 2, pd::Status::kSeparated, 0.0);
  f.pair(2, 3, pd::Status::kFalsePositive, 0.1 / 3);
  f.pair(0, 4, pd::Status::kError, 0);
  f.run.pairs[0].at = pd::Vec3(1.0 / 3, -2.5e-7, 1e300);
  const std::string csv = pd::render_csv(f.input());
  std::string error;
  const CsvRows rows = parse_csv(csv, error);
  ASSERT_EQ(error, "") << csv;
  ASSERT_EQ(rows.size(), 4u) << csv;  // the header, and every pair but the separated one
  const std::vector<std::string> header = {
      "a",           "b",      "fingerprint", "status", "depth", "depth_source", "tolerance",
      "margin",      "units",  "at_x",        "at_y",   "at_z",  "group",        "baseline_state",
      "suppression", "message"};
  EXPECT_EQ(rows[0], header);
  for (const auto& r : rows) EXPECT_EQ(r.size(), header.size());
  EXPECT_EQ(rows[1][0], "plain");
  EXPECT_EQ(rows[1][1], "comma, id");
  EXPECT_EQ(rows[1][2], pd::pair_fingerprint("plain", "comma, id"));
  EXPECT_EQ(rows[1][3], "interference");
  // Numbers read back to the same doubles.
  EXPECT_EQ(std::stod(rows[1][4]), 0.3);
  EXPECT_EQ(rows[1][5], "hull");  // which quantity the depth is
  EXPECT_EQ(std::stod(rows[1][7]), 0.1 - 0.3);
  EXPECT_EQ(std::stod(rows[1][9]), 1.0 / 3);
  EXPECT_EQ(std::stod(rows[1][10]), -2.5e-7);
  EXPECT_EQ(std::stod(rows[1][11]), 1e300);
  EXPECT_EQ(rows[2][0], "quote \"q\"");
  EXPECT_EQ(rows[2][1], "line\nbreak");
  EXPECT_EQ(std::stod(rows[2][4]), 0.1 / 3);
  EXPECT_EQ(rows[2][9], "");  // no `at`: empty, not invented
  EXPECT_EQ(rows[3][3], "error");
  EXPECT_EQ(rows[3][4], "");  // an error has no depth or margin
  EXPECT_EQ(rows[3][7], "");
  EXPECT_EQ(rows[3][15], "plain / far: error: worker crashed, signal 11");
  // Quoted exactly where needed.
  EXPECT_NE(csv.find("\r\nplain,\"comma, id\","), std::string::npos) << csv;
  EXPECT_NE(csv.find("\r\n\"quote \"\"q\"\"\",\"line\nbreak\","), std::string::npos) << csv;
}
