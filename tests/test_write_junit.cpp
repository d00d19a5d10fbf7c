// The JUnit XML writer (--junit, write_junit.cpp) in process: valid against
// the Jenkins JUnit schema (tests/schemas, xmllint), a test case per candidate
// pair and per failed part, the counts CI views show, names that stay stable
// and escaped.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include "bcf_check.h"
#include "cli_support.h"
#include "report_fixture.h"
#include "results/fingerprint.h"

using namespace pd;
using namespace pd::test;

namespace {

/// The value of attribute `name` of the first element `tag`.
std::string attribute(const std::string& xml, const std::string& tag, const std::string& name) {
  std::smatch m;
  const std::regex re("<" + tag + "( [^>]*)? " + name + "=\"([^\"]*)\"");
  return std::regex_search(xml, m, re) ? m[2].str() : "(none)";
}

}  // namespace

TEST(WriteJunit, ValidAndCountsEveryCaseOnce) {
  ReportFixture f = every_status();
  const std::string xml = render_junit(f.input());
  PD_REQUIRE_TOOL(have_command("xmllint"), "xmllint (libxml2-utils)");
  const std::string path = process_temp("junit.xml");
  std::ofstream(path) << xml;
  EXPECT_EQ(validate_xml(kSource + "/tests/schemas/jenkins-junit.xsd", path), "") << xml;
  // Six candidate pairs and the failed part; the two interferences fail (the
  // default bar), the failed, undecided pair and the part are errors.
  EXPECT_EQ(attribute(xml, "testsuite", "tests"), "7");
  EXPECT_EQ(attribute(xml, "testsuite", "failures"), "2");
  EXPECT_EQ(attribute(xml, "testsuite", "errors"), "3");
  EXPECT_EQ(attribute(xml, "testsuite", "skipped"), "0");
  EXPECT_EQ(attribute(xml, "testsuites", "tests"), "7");
  EXPECT_EQ(count_of(xml, "<testcase "), 7u);
  EXPECT_EQ(count_of(xml, "<failure type=\"interference\""), 2u);
  EXPECT_EQ(count_of(xml, "<error type=\"error\""), 1u);
  EXPECT_EQ(count_of(xml, "<error type=\"undecided\""), 1u);
  EXPECT_EQ(count_of(xml, "<error type=\"part_error\""), 1u);
  EXPECT_NE(xml.find("<property name=\"exit_code\" value=\"3\"/>"), std::string::npos) << xml;
  EXPECT_NE(xml.find("<property name=\"fail_on\" value=\"interference\"/>"), std::string::npos);
  EXPECT_NE(xml.find("<property name=\"tolerance\" value=\"0.1 mm\"/>"), std::string::npos);
}

TEST(WriteJunit, CaseNamesAreSortedIdsAndTheFingerprintEscaped) {
  ReportFixture f = every_status();
  const std::string xml = render_junit(f.input());
  // "frame" < "lid <&>" bytewise; the fingerprint keeps the name unique and stable.
  const std::string fp = pair_fingerprint("frame", "lid <&>");
  EXPECT_NE(xml.find("name=\"frame ~ lid &lt;&amp;&gt; [" + fp + "]\""), std::string::npos) << xml;
  // b first when it sorts first: the same name whichever part is a.
  const std::string fp2 = pair_fingerprint("bolt", "pin");
  EXPECT_NE(xml.find("name=\"bolt ~ pin [" + fp2 + "]\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("name=\"part bad\""), std::string::npos);
  EXPECT_EQ(xml.find("lid <&>"), std::string::npos) << "an id left unescaped";
  EXPECT_NE(xml.find("part bad could not be used: unreadable: no such file"), std::string::npos);
}

TEST(WriteJunit, ClassNameIsTheSceneStemWithoutDots) {
  ReportFixture f = every_status();
  f.context.scene_path = "runs/nightly.v2.json";
  std::string xml = render_junit(f.input());
  EXPECT_EQ(attribute(xml, "testcase", "classname"), "pdcheck.nightly_v2");
  EXPECT_EQ(attribute(xml, "testsuite", "name"), "runs/nightly.v2.json");
  f.context.scene_path = "-";  // a scene on standard input
  xml = render_junit(f.input());
  EXPECT_EQ(attribute(xml, "testsuite", "name"), "stdin");
  EXPECT_EQ(attribute(xml, "testcase", "classname"), "pdcheck.stdin");
}

TEST(WriteJunit, TheBarDecidesWhichFindingsFail) {
  ReportFixture f = every_status();
  f.options.fail_on = FailOn::kAny;  // the false positive fails too
  std::string xml = render_junit(f.input());
  EXPECT_EQ(attribute(xml, "testsuite", "failures"), "3");
  EXPECT_EQ(count_of(xml, "<failure type=\"false_positive\""), 1u);
  f.options.fail_on = FailOn::kNone;  // nothing fails; errors stay errors
  xml = render_junit(f.input());
  EXPECT_EQ(attribute(xml, "testsuite", "failures"), "0");
  EXPECT_EQ(attribute(xml, "testsuite", "errors"), "3");
}
