// The files beside a report (extra_outputs.cpp): every path checked before
// the work, each file written with its writer's bytes, none not asked for.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "cli_support.h"
#include "output_error.h"
#include "report/extra_outputs.h"
#include "report/review_text.h"
#include "report_fixture.h"

using namespace pd;
using namespace pd::test;
namespace fs = std::filesystem;

TEST(ExtraOutputs, EachFileHasItsWritersBytes) {
  const fs::path d = fs::path(testing::TempDir()) / ("extra_outputs_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  ExtraOutputPaths paths;
  paths.junit = (d / "j.xml").string();
  paths.sarif = (d / "s.sarif").string();
  paths.csv = (d / "c.csv").string();
  paths.write_suppressions = (d / "w.json").string();
  const ExtraOutputs out = check_extra_outputs(paths);
  EXPECT_FALSE(out.html);
  EXPECT_FALSE(out.bcf);
  ReportFixture f = every_status();
  f.options.today = "2024-05-01";
  const ReportInput in = f.input();
  bool page_made = false;
  write_extra_outputs(out, in, [&] {
    page_made = true;
    return std::string("<html>");
  });
  EXPECT_FALSE(page_made);  // not asked for: not rendered
  EXPECT_EQ(read_text(*paths.junit), render_junit(in));
  EXPECT_EQ(read_text(*paths.sarif), render_sarif(in));
  EXPECT_EQ(read_text(*paths.csv), render_csv(in));
  EXPECT_EQ(read_text(*paths.write_suppressions), suppressions_to_write(in, "2024-05-01"));
  size_t files = 0;
  for (const auto& e : fs::directory_iterator(d)) files += e.is_regular_file();
  EXPECT_EQ(files, 4u);
}

TEST(ExtraOutputs, ABadPathFailsBeforeAnyWorkNamingItsOption) {
  ExtraOutputPaths paths;
  paths.junit = process_dir() + "fine.xml";
  paths.bcf = "/nonexistent-dir/out.bcf";
  try {
    check_extra_outputs(paths);
    ADD_FAILURE() << "an unwritable --bcf path was accepted";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("--bcf /nonexistent-dir/out.bcf"), std::string::npos)
        << e.what();
  }
}
