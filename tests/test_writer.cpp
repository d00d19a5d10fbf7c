// The report-writer table (writer.cpp): the --format names, each found by
// name and rendering what its own function renders.
#include <gtest/gtest.h>

#include "report_fixture.h"

using namespace pd;
using namespace pd::test;

TEST(Writer, TheFormatsAndTheirRenderers) {
  std::vector<std::string> names;
  for (const ReportFormat& f : report_formats()) {
    names.push_back(f.name);
    EXPECT_EQ(find_report_format(f.name), &f);
    EXPECT_NE(std::string(f.description), "");
  }
  EXPECT_EQ(names, (std::vector<std::string>{"json", "jsonl", "junit", "sarif", "table"}));
  EXPECT_EQ(find_report_format("json")->render, &render_json);
  EXPECT_EQ(find_report_format("jsonl")->render, &render_jsonl);
  EXPECT_EQ(find_report_format("junit")->render, &render_junit);
  EXPECT_EQ(find_report_format("sarif")->render, &render_sarif);
  EXPECT_EQ(find_report_format("table")->render, &render_table);
  // The exports are files of their own options, not formats of the report.
  EXPECT_EQ(find_report_format("csv"), nullptr);
  EXPECT_EQ(find_report_format("bcf"), nullptr);
  EXPECT_EQ(find_report_format("JSON"), nullptr);
  EXPECT_EQ(find_report_format(""), nullptr);
}

TEST(Writer, EveryFormatRendersTheSameRunTheSameWay) {
  ReportFixture f = every_status();
  const ReportInput in = f.input();
  for (const ReportFormat& format : report_formats()) {
    const std::string once = format.render(in);
    EXPECT_FALSE(once.empty()) << format.name;
    EXPECT_EQ(once.back(), '\n') << format.name;
    EXPECT_EQ(format.render(in), once) << format.name << " depends on more than its input";
  }
}
