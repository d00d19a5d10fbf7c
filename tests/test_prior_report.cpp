// An old report read for --reuse (prior_report.cpp): its settings hash, its
// usable parts' content hashes and its pairs by fingerprint; a report it
// cannot use is a user error naming the file.
#include <gtest/gtest.h>

#include <fstream>

#include "batch/reuse.h"
#include "bcf_check.h"
#include "report/input_error.h"
#include "report/prior_report.h"
#include "report_fixture.h"
#include "results/fingerprint.h"

using namespace pd;
using namespace pd::test;

TEST(PriorReport, ReadsWhatReuseNeeds) {
  ReportFixture f = every_status();
  f.run.scene_hash = "scene-hash";
  f.run.settings_hash = "settings-hash";
  f.run.part_hashes = {"h0", "h1", "h2", "h3", "h4"};
  const std::string path = process_temp("prior.json");
  std::ofstream(path) << render_json(f.input());
  PriorSettings settings;
  const PriorResults prior = load_prior_report(path, &settings);
  EXPECT_EQ(prior.path, path);
  EXPECT_EQ(prior.settings_hash, "settings-hash");
  // The failed part's hash is no promise of anything: left out.
  EXPECT_EQ(prior.part_hash,
            (std::map<std::string, std::string>{
                {"frame", "h0"}, {"lid <&>", "h1"}, {"pin", "h2"}, {"bolt", "h3"}}));
  ASSERT_EQ(prior.pairs.size(), f.run.pairs.size());
  const PairResult& lid = prior.pairs.at(pair_fingerprint("frame", "lid <&>"));
  EXPECT_EQ(lid.status, Status::kInterference);
  EXPECT_EQ(lid.depth, 1.0);
  EXPECT_EQ(lid.a, -1);  // indices are the reusing run's
  EXPECT_EQ(prior.pairs.at(pair_fingerprint("pin", "bolt")).error, "worker crashed, signal 11");
  EXPECT_EQ(settings.units, "mm");
  EXPECT_EQ(settings.tolerance, 0.1);
}

TEST(PriorReport, AReportItCannotUseNamesTheFile) {
  auto error_of = [](const std::string& name, const std::string& text) {
    const std::string path = process_temp(name);
    std::ofstream(path) << text;
    try {
      load_prior_report(path);
    } catch (const ReportInputError& e) {
      return std::string(e.what()).substr(path.size());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(error_of("p1.json", "{\"pairs\": []}").rfind(": $.hashes: missing; --reuse needs", 0),
            0u);
  EXPECT_EQ(error_of("p2.json", "not json").rfind(": not a JSON report (", 0), 0u);
  EXPECT_EQ(
      error_of("p3.json", R"({"hashes": {"settings": "s"}})").rfind(": not a pdcheck report: ", 0),
      0u);
  EXPECT_EQ(error_of("p4.json", R"({"hashes": {"settings": "s"}, "parts": [],
                                   "pairs": [{"a": "x", "b": "y", "status": "bogus"}]})")
                .rfind(": $.pairs[0]: ", 0),
            0u);
}
