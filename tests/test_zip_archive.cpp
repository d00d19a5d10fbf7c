// The zip archive of the BCF export (zip_archive.cpp): the same bytes for the
// same entries, listed back by unzip.
#include <gtest/gtest.h>

#include <cstdlib>
#include <ctime>
#include <fstream>

#include "bcf_check.h"
#include "zip_archive.h"

using namespace pd::test;

// libzip dates entries through localtime(): the bytes must not depend on the zone.
TEST(ZipArchive, BytesDoNotDependOnTheTimeZone) {
  const std::vector<pd::ZipEntry> entries = {{"bcf.version", "<Version VersionId=\"3.0\"/>"},
                                             {"d/", ""},
                                             {"d/x.xml", std::string(5000, 'x')}};
  const char* old = std::getenv("TZ");
  const std::string saved = old ? old : "";
  std::string first;
  // POSIX zones (no tzdata needed): UTC, +5:45, −3:30, and +12:45 with summer time.
  for (const char* tz : {"UTC0", "XST-5:45", "YST3:30", "NZST-12:45NZDT,M9.5.0,M4.1.0/3"}) {
    setenv("TZ", tz, 1);
    tzset();
    const std::string z = pd::zip_archive(entries);
    if (first.empty()) first = z;
    EXPECT_EQ(z, first) << "TZ=" << tz;
  }
  if (old)
    setenv("TZ", saved.c_str(), 1);
  else
    unsetenv("TZ");
  tzset();
  // The directory entry is there, and the date is the fixed one.
  const std::string path = process_temp("exports_tz.zip");
  std::ofstream(path, std::ios::binary) << first;
  const CliResult l = shell("unzip -l " + path);
  EXPECT_EQ(l.code, 0) << l.err;
  EXPECT_NE(l.out.find("1980-01-01 00:00   d/\n"), std::string::npos) << l.out;
  EXPECT_EQ(count_of(l.out, "1980-01-01 00:00"), 3u) << l.out;
}
