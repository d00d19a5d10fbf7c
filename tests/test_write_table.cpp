// --format table (write_table.cpp), what a terminal shows without -o: the
// verdict, then the findings, interference first. Through the binary on a
// pseudo-terminal: test_cli.cpp.
#include <gtest/gtest.h>

#include "report_fixture.h"

using namespace pd;
using namespace pd::test;

namespace {

// The table's lines from its header row on.
std::vector<std::string> table_rows_of(const std::string& table) {
  std::vector<std::string> rows;
  size_t at = table.find("\nstatus ");
  if (at == std::string::npos) return rows;
  for (++at; at < table.size() && table[at] != '\n' && table.compare(at, 3, "...") != 0;) {
    const size_t end = table.find('\n', at);
    rows.push_back(table.substr(at, end - at));
    at = end + 1;
  }
  return rows;
}

// A row: its status first, then its depth cell, then "a / b" and the note.
bool table_row_is(const std::string& row, const std::string& status, const std::string& depth,
                  const std::string& rest) {
  const size_t d = row.find_first_not_of(' ', status.size());
  return row.rfind(status + " ", 0) == 0 && d != std::string::npos &&
         row.compare(d, depth.size(), depth) == 0 &&
         row.find_first_not_of(' ', d + depth.size()) == row.find(rest) &&
         row.size() == row.find(rest) + rest.size();
}

}  // namespace

TEST(WriteTable, TheVerdictThenTheFindingsWorstFirst) {
  ReportFixture f = every_status();
  const std::string table = render_table(f.input());
  // Incomplete (the undecided and failed pairs, the unusable part): never a pass.
  EXPECT_EQ(table.rfind("pdcheck: scene.json: INCOMPLETE: not every pair was checked", 0), 0u)
      << table;
  EXPECT_NE(table.find("2 interferences, 1 false positive, 1 separated of"), std::string::npos)
      << table;
  const std::vector<std::string> rows = table_rows_of(table);
  ASSERT_EQ(rows.size(), 6u) << table;  // the header and every finding, the separated pair not
  EXPECT_TRUE(table_row_is(rows[0], "status", "depth (mm)", "parts")) << rows[0];
  EXPECT_TRUE(table_row_is(rows[1], "interference", "1", "frame / lid <&>")) << rows[1];
  EXPECT_TRUE(table_row_is(rows[2], "interference", "0.3", "lid <&> / pin")) << rows[2];
  EXPECT_TRUE(
      table_row_is(rows[3], "undecided", "0.05 to 0.2", "lid <&> / bolt: work box exhausted"))
      << rows[3];
  EXPECT_TRUE(table_row_is(rows[4], "error", "-", "pin / bolt: worker crashed, signal 11"))
      << rows[4];
  EXPECT_TRUE(table_row_is(rows[5], "false_positive", "0.05", "frame / pin")) << rows[5];
  // The columns line up.
  for (const std::string& r : rows) EXPECT_EQ(r.find_first_not_of(' ', 14), 16u) << r;
  EXPECT_EQ(table.find("frame / bolt"), std::string::npos) << "a separated pair is listed";
  EXPECT_NE(table.find("--format json"), std::string::npos) << table;
}

TEST(WriteTable, AShortTableOfALongRunAndACleanOne) {
  ReportFixture f;
  for (int k = 0; k < 30; ++k) f.part("p" + std::to_string(k));
  for (int k = 0; k + 1 < 30; ++k)
    f.pair(k, k + 1, Status::kFalsePositive, 0.001 * (k + 1)).direction = Vec3::UnitZ();
  const std::string many = render_table(f.input());
  EXPECT_EQ(many.rfind("pdcheck: scene.json: PASS: no interference (exit code 0)\n", 0), 0u)
      << many;
  EXPECT_NE(many.find("... and 9 more findings"), std::string::npos) << many;
  const std::vector<std::string> rows = table_rows_of(many);
  ASSERT_EQ(rows.size(), 21u) << many;  // the header and 20 findings
  EXPECT_TRUE(table_row_is(rows[1], "false_positive", "0.029", "p28 / p29")) << "deepest first:\n"
                                                                             << many;
  EXPECT_TRUE(table_row_is(rows[20], "false_positive", "0.01", "p9 / p10")) << many;

  ReportFixture clean;
  clean.part("a");
  clean.part("b");
  clean.pair(0, 1, Status::kSeparated, 0.0);
  const std::string none = render_table(clean.input());
  EXPECT_NE(none.find("PASS: no interference"), std::string::npos) << none;
  EXPECT_NE(none.find("No findings: every candidate pair is separated."), std::string::npos)
      << none;
}
