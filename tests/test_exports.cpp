// The exports (--csv, --bcf; docs/report-format.md) through the binary: the
// CSV parsed back by a strict RFC 4180 reader and checked against the JSON
// report; every BCF validated against buildingSMART's BCF 3.0 schemas
// (tests/bcf_check.h); the same bytes for the same input, in any time zone,
// and from a merge of shards as from the unsharded run. The writers alone:
// test_write_csv.cpp, test_write_bcf.cpp, test_bcf_topics.cpp,
// test_bcf_view.cpp, test_zip_archive.cpp.
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "bcf_check.h"
#include "cli_support.h"
#include "csv_reader.h"
#include "cube_json.h"
#include "report/bcf_topics.h"
#include "results/fingerprint.h"

using nlohmann::json;
using namespace pd::test;

using pd_test::cube_json;

namespace {

// An L-shaped prism (nonconvex): a block in its arm is a `thickness` pair with `at`.
std::string ell_mesh() {
  const double p[6][2] = {{0, 0}, {10, 0}, {10, 2}, {2, 2}, {2, 10}, {0, 10}};
  std::string obj;
  for (const double z : {0.0, 2.0})
    for (const auto& q : p)
      obj +=
          "v " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(z) + "\n";
  auto face = [&](int a, int b, int c) {
    obj += "f " + std::to_string(a + 1) + " " + std::to_string(b + 1) + " " +
           std::to_string(c + 1) + "\n";
  };
  for (int t = 1; t < 5; ++t) {
    face(0, t + 1, t);
    face(6, 6 + t, 6 + t + 1);
  }
  for (int i = 0; i < 6; ++i) {
    const int j = (i + 1) % 6;
    face(i, j, j + 6);
    face(i, j + 6, i + 6);
  }
  return write_temp("exports_ell.obj", obj);
}

// A frame with a lid (`lid_z` 10 rests on it, 9 sinks 1 in), a press-fit
// bushing (0.5 in: suppressed), a pin 0.05 in (a false positive), a bolt far
// away, and an L-shaped mesh with a block in its arm. Ids with a comma and a
// quote test the CSV's quoting.
std::string scene(const std::string& name, double lid_z) {
  const json ell = {{"id", "ell"},
                    {"mesh", ell_mesh()},
                    {"transform", {1, 0, 0, 100, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}};
  const json parts = {
      cube_json("frame", 0, 0, 0, 10),          cube_json("lid, top", 0, 0, lid_z, 10),
      cube_json("bushing \"A\"", 9.5, 2, 2, 4), cube_json("pin", -1.95, 4, 4, 2),
      cube_json("bolt", 40, 0, 0, 2),           ell,
      cube_json("block", 107, 1.5, 0.5, 1)};
  return write_temp(name, json{{"units", "mm"}, {"tolerance", 0.1}, {"parts", parts}}.dump());
}

json read_json(const std::string& path) {
  return json::parse(read_text(path));
}

std::string suppressions_file() {
  return write_temp(
      "exports_sup.json",
      json{{"suppressions",
            {{{"a", "bushing \"A\""}, {"b", "frame"}, {"reason", "press fit, drawing \"4711\""}}}}}
          .dump());
}

/// The baseline run (lid resting) and the checked run's common options.
struct Runs {
  std::string baseline, suppressions, args;
};
const Runs& runs() {
  static const Runs r = [] {
    Runs x;
    x.baseline = process_temp("exports_r1.json");
    EXPECT_EQ(pdcheck(scene("exports_s1.json", 10.0) + " -q -o " + x.baseline).code, 1);
    x.suppressions = suppressions_file();
    x.args = " -q --baseline " + x.baseline + " --suppressions " + x.suppressions;
    return x;
  }();
  return r;
}

/// A number as the JSON report's text has it.
std::string number_text(const json& j) {
  return j.dump();
}

}  // namespace

// Through the binary: the CSV's rows are the report's non-separated pairs,
// field for field; the BCF validates and holds a topic per finding that needs
// a person; a second run in another time zone writes the same bytes.
TEST(Exports, CsvAndBcfMatchTheReport) {
  const Runs& base = runs();
  const std::string report = process_temp("exports_r2.json"), csv = process_temp("exports.csv"),
                    bcf = process_temp("exports.bcf");
  const CliResult r = pdcheck(scene("exports_s2.json", 9.0) + base.args + " -o " + report +
                              " --csv " + csv + " --bcf " + bcf);
  ASSERT_EQ(r.code, 1) << r.err;
  const json rep = read_json(report);

  std::string error;
  const CsvRows rows = parse_csv(read_text(csv), error);
  ASSERT_EQ(error, "");
  ASSERT_FALSE(rows.empty());
  std::map<std::string, size_t> col;
  for (size_t k = 0; k < rows[0].size(); ++k) col[rows[0][k]] = k;
  size_t row = 1;
  std::set<std::string> needs_topic;
  for (const json& p : rep["pairs"]) {
    if (p["status"] == "separated") continue;
    ASSERT_LT(row, rows.size()) << "no row for " << p.dump();
    const auto& c = rows[row++];
    EXPECT_EQ(c[col["a"]], p["a"]);
    EXPECT_EQ(c[col["b"]], p["b"]);
    EXPECT_EQ(c[col["fingerprint"]], p["fingerprint"]);
    EXPECT_EQ(c[col["status"]], p["status"]);
    EXPECT_EQ(c[col["depth"]], number_text(p["depth"]));
    EXPECT_EQ(std::stod(c[col["depth"]]), p["depth"].get<double>());  // round trip
    EXPECT_EQ(c[col["depth_source"]], p["depth_source"]);
    EXPECT_EQ(c[col["margin"]], number_text(p["margin"]));
    EXPECT_EQ(c[col["tolerance"]], number_text(rep["tolerance"]));
    EXPECT_EQ(c[col["units"]], "mm");
    EXPECT_EQ(c[col["baseline_state"]], p.value("baseline_state", ""));
    EXPECT_EQ(c[col["suppression"]],
              p.contains("suppressed") ? p["suppressed"]["reason"].get<std::string>() : "");
    EXPECT_EQ(c[col["group"]], p.value("group", ""));
    ASSERT_TRUE(p.contains("at")) << p.dump();  // every decided finding says where
    EXPECT_EQ(c[col["at_x"]], number_text(p["at"][0]));
    EXPECT_EQ(c[col["at_z"]], number_text(p["at"][2]));
    if (p["status"] != "false_positive") needs_topic.insert(p["fingerprint"]);
  }
  EXPECT_EQ(row, rows.size());
  // What the scene holds, so the checks above had something to check.
  const std::string all = read_text(csv);
  EXPECT_NE(all.find("\"lid, top\""), std::string::npos);
  EXPECT_NE(all.find("\"bushing \"\"A\"\"\""), std::string::npos);
  EXPECT_NE(all.find(",false_positive,"), std::string::npos);
  EXPECT_NE(all.find(",new,"), std::string::npos);
  EXPECT_NE(all.find("\"press fit, drawing \"\"4711\"\"\""), std::string::npos);
  EXPECT_EQ(rows.size(), 5u);  // lid, bushing, pin, ell/block

  const std::string dir = process_temp("exports_bcf");
  const std::vector<std::string> topics = check_bcf(bcf, dir);
  std::set<std::string> want;
  for (const std::string& fp : needs_topic) want.insert(pd::bcf_guid("topic", fp));
  EXPECT_EQ(std::set<std::string>(topics.begin(), topics.end()), want);
  EXPECT_EQ(topics.size(), 3u);  // lid, bushing (suppressed), ell/block; not the pin
  const std::string lid = pd::bcf_guid("topic", pd::pair_fingerprint("frame", "lid, top"));
  const std::string bushing = pd::bcf_guid("topic", pd::pair_fingerprint("frame", "bushing \"A\""));
  const std::string ell = pd::bcf_guid("topic", pd::pair_fingerprint("ell", "block"));
  const std::string m_lid = read_text(dir + "/" + lid + "/markup.bcf");
  EXPECT_NE(m_lid.find("TopicType=\"Interference\" TopicStatus=\"Open\""), std::string::npos)
      << m_lid;
  EXPECT_NE(m_lid.find("<Label>new</Label>"), std::string::npos) << m_lid;
  EXPECT_NE(m_lid.find("<CreationAuthor>pdcheck</CreationAuthor>"), std::string::npos);
  EXPECT_NE(m_lid.find("depth 1 mm &gt; tolerance 0.1 mm"), std::string::npos) << m_lid;
  EXPECT_NE(m_lid.find("<Viewpoint>viewpoint.bcfv</Viewpoint>"), std::string::npos);
  const std::string m_bushing = read_text(dir + "/" + bushing + "/markup.bcf");
  EXPECT_NE(m_bushing.find("TopicStatus=\"Closed\""), std::string::npos) << m_bushing;
  EXPECT_NE(m_bushing.find("<Label>suppressed</Label>"), std::string::npos) << m_bushing;
  const std::string v_lid = read_text(dir + "/" + lid + "/viewpoint.bcfv");
  EXPECT_EQ(count_of(v_lid, "<OriginatingSystem>pdcheck</OriginatingSystem>"),
            4u);  // selected, coloured
  EXPECT_NE(v_lid.find("<AuthoringToolId>lid, top</AuthoringToolId>"), std::string::npos);
  EXPECT_NE(v_lid.find("<AuthoringToolId>frame</AuthoringToolId>"), std::string::npos);
  EXPECT_NE(v_lid.find("<Lines>"), std::string::npos);  // its `at`: the depth as a line
  const std::string v_bushing = read_text(dir + "/" + bushing + "/viewpoint.bcfv");
  EXPECT_NE(v_bushing.find("<AuthoringToolId>bushing &quot;A&quot;</AuthoringToolId>"),
            std::string::npos)
      << v_bushing;
  // The thickness pair: its camera in metres looks at its `at`, and its depth is a line.
  const std::string v_ell = read_text(dir + "/" + ell + "/viewpoint.bcfv");
  json at;
  for (const json& p : rep["pairs"])
    if (p["a"] == "ell") at = p["at"];
  ASSERT_TRUE(at.is_array()) << rep.dump();
  const size_t start = v_ell.find("<StartPoint>");
  ASSERT_NE(start, std::string::npos) << v_ell;
  const size_t x = v_ell.find("<X>", start) + 3;
  EXPECT_NEAR(std::stod(v_ell.substr(x, v_ell.find("</X>", x) - x)), at[0].get<double>() / 1000,
              1e-15);
  EXPECT_EQ(count_of(v_ell, "<Line>"), 1u);

  // The same run again, in another time zone: the same bytes.
  const std::string csv2 = process_temp("exports2.csv"), bcf2 = process_temp("exports2.bcf");
  const CliResult r2 = pdcheck(scene("exports_s2.json", 9.0) + base.args + " --csv " + csv2 +
                                   " --bcf " + bcf2 + " -o /dev/null",
                               "", "TZ=XST-5:45");  // POSIX: no tzdata needed
  ASSERT_EQ(r2.code, 1) << r2.err;
  EXPECT_EQ(read_text(csv2), read_text(csv));
  EXPECT_TRUE(read_text(bcf2) == read_text(bcf)) << "the BCF's bytes differ between runs";
}

// pdcheck merge writes the unsharded run's CSV and BCF, byte for byte; a
// shard alone refuses them (they describe the whole run).
TEST(Exports, ShardsMergedWriteTheUnshardedExports) {
  const Runs& base = runs();
  const std::string s = scene("exports_s3.json", 9.0);
  const std::string csv = process_temp("exports_full.csv"), bcf = process_temp("exports_full.bcf");
  ASSERT_EQ(pdcheck(s + base.args + " -o /dev/null --csv " + csv + " --bcf " + bcf).code, 1);
  std::string shards;
  for (int k = 1; k <= 3; ++k) {
    const std::string out = process_temp("exports_shard" + std::to_string(k) + ".json");
    const CliResult r = pdcheck(s + " -q --shard " + std::to_string(k) + "/3 -o " + out);
    ASSERT_NE(r.code, 2) << r.err;
    shards += " " + out;
  }
  const std::string mcsv = process_temp("exports_merged.csv"),
                    mbcf = process_temp("exports_merged.bcf");
  const CliResult m =
      pdcheck("merge" + shards + base.args + " -o /dev/null --csv " + mcsv + " --bcf " + mbcf);
  ASSERT_EQ(m.code, 1) << m.err;
  EXPECT_EQ(read_text(mcsv), read_text(csv));
  EXPECT_TRUE(read_text(mbcf) == read_text(bcf)) << "the merged BCF differs from the run's";
  EXPECT_EQ(check_bcf(mbcf, process_temp("exports_merged_bcf")).size(), 3u);

  const CliResult refused =
      pdcheck(s + " -q --shard 1/3 -o /dev/null --bcf " + process_temp("x.bcf"));
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.err.find("--bcf applies to the whole run"), std::string::npos) << refused.err;
}

// Paths are checked before the run, as every other output's.
TEST(Exports, BadPathsFailBeforeTheRun) {
  for (const std::string opt : {"--csv", "--bcf"}) {
    const CliResult r =
        pdcheck(scene("exports_bad.json", 9.0) + " -q " + opt + " /no/such/dir/out");
    EXPECT_EQ(r.code, 2) << opt << ": " << r.err;
    EXPECT_NE(r.err.find(opt + " /no/such/dir/out"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << "the run went ahead";
  }
}
