// Checks a BCF export (--bcf) as a BCF reader would: its zip layout listed by
// unzip and every file validated against buildingSMART's BCF 3.0 schemas
// (tests/schemas/bcf-3.0, xmllint).
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.h"

namespace pd::test {

/// A path of this test process's own, with nothing there yet: other test
/// processes (sanitizer builds, worktrees) may run these tests at the same time.
inline std::string process_temp(const std::string& name) {
  const std::string p = process_dir() + name;
  std::remove(p.c_str());
  return p;
}

/// How often `what` occurs in `text`.
inline size_t count_of(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// Every entry of a BCF zip, in order (unzip -Z1), and its files unpacked in `dir`.
inline std::vector<std::string> unpack_bcf(const std::string& bcf, const std::string& dir) {
  const CliResult list = shell("unzip -Z1 " + bcf);
  EXPECT_EQ(list.code, 0) << list.err;
  std::vector<std::string> names;
  std::istringstream in(list.out);
  for (std::string line; std::getline(in, line);) names.push_back(line);
  const CliResult u =
      shell("rm -rf " + dir + " && mkdir -p " + dir + " && unzip -q " + bcf + " -d " + dir);
  EXPECT_EQ(u.code, 0) << u.err;
  return names;
}

/// Validates every file of an unpacked BCF against its BCF 3.0 schema and
/// checks the layout: bcf.version, extensions.xml, then per topic its folder,
/// markup.bcf and viewpoint.bcfv. Returns the topic GUIDs in order.
inline std::vector<std::string> check_bcf(const std::string& bcf, const std::string& dir) {
  // Not skipped: CI installs both (scripts/setup.sh), and an unvalidated BCF proves nothing.
  EXPECT_TRUE(have_command("xmllint")) << "xmllint (libxml2-utils) is required";
  EXPECT_TRUE(have_command("unzip")) << "unzip is required";
  const std::vector<std::string> names = unpack_bcf(bcf, dir);
  const std::string xsd = kSource + "/tests/schemas/bcf-3.0/";
  EXPECT_GE(names.size(), 2u);
  if (names.size() < 2) return {};
  EXPECT_EQ(names[0], "bcf.version");
  EXPECT_EQ(names[1], "extensions.xml");
  EXPECT_EQ(validate_xml(xsd + "version.xsd", dir + "/bcf.version"), "");
  EXPECT_EQ(validate_xml(xsd + "extensions.xsd", dir + "/extensions.xml"), "");
  EXPECT_NE(read_text(dir + "/bcf.version").find("VersionId=\"3.0\""), std::string::npos);
  EXPECT_EQ((names.size() - 2) % 3, 0u);
  const std::regex guid("[a-f0-9]{8}-[a-f0-9]{4}-8[a-f0-9]{3}-[89ab][a-f0-9]{3}-[a-f0-9]{12}");
  std::vector<std::string> topics;
  for (size_t k = 2; k + 2 < names.size(); k += 3) {
    const std::string g = names[k].substr(0, names[k].size() - 1);
    EXPECT_TRUE(std::regex_match(g, guid)) << names[k];
    EXPECT_EQ(names[k], g + "/");
    EXPECT_EQ(names[k + 1], g + "/markup.bcf");
    EXPECT_EQ(names[k + 2], g + "/viewpoint.bcfv");
    EXPECT_EQ(validate_xml(xsd + "markup.xsd", dir + "/" + names[k + 1]), "");
    EXPECT_EQ(validate_xml(xsd + "visinfo.xsd", dir + "/" + names[k + 2]), "");
    EXPECT_NE(read_text(dir + "/" + names[k + 1]).find("<Topic Guid=\"" + g + "\""),
              std::string::npos);
    topics.push_back(g);
  }
  return topics;
}

}  // namespace pd::test
