// The exports (--csv, --bcf; docs/report-format.md): the CSV parsed back by a
// strict RFC 4180 reader and checked against the JSON report; every BCF a test
// writes validated against buildingSMART's BCF 3.0 schemas (tests/schemas/bcf-3.0,
// xmllint) and its zip layout listed; the same bytes for the same input, in
// any time zone, and from a merge of shards as from the unsharded run.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "cli_support.h"
#include "report/bcf_topics.h"
#include "report/bcf_view.h"
#include "report/writer.h"
#include "report/zip_archive.h"
#include "results/fingerprint.h"
#include "tolerances.h"

using nlohmann::json;
using namespace pd::test;

namespace {

using Rows = std::vector<std::vector<std::string>>;

/// A strict RFC 4180 reader: every record ends in CRLF, a field is quoted or
/// holds no comma, quote, CR or LF, quotes inside a quoted field are doubled.
/// Sets `error` on anything else.
Rows parse_csv(const std::string& text, std::string& error) {
  Rows rows;
  std::vector<std::string> row;
  std::string f;
  size_t k = 0;
  while (k < text.size()) {
    if (text[k] == '"') {
      for (++k;; ++k) {
        if (k >= text.size()) {
          error = "unterminated quoted field";
          return rows;
        }
        if (text[k] == '"') {
          if (k + 1 < text.size() && text[k + 1] == '"') {
            f += '"';
            ++k;
          } else {
            ++k;
            break;
          }
        } else {
          f += text[k];
        }
      }
    } else {
      while (k < text.size() && text[k] != ',' && text[k] != '\r') {
        if (text[k] == '"' || text[k] == '\n') {
          error = "bare quote or LF at byte " + std::to_string(k);
          return rows;
        }
        f += text[k++];
      }
    }
    row.push_back(std::move(f));
    f.clear();
    if (k < text.size() && text[k] == ',') {
      ++k;
    } else if (text.compare(k, 2, "\r\n") == 0) {
      k += 2;
      rows.push_back(std::move(row));
      row.clear();
    } else {
      error = "a record not ended by CRLF at byte " + std::to_string(k);
      return rows;
    }
  }
  if (!row.empty()) error = "the last record has no CRLF";
  return rows;
}

json cube(const std::string& id, double x, double y, double z, double s) {
  json v = json::array();
  for (int k = 0; k < 8; ++k)
    v.push_back({x + s * (k & 1), y + s * ((k >> 1) & 1), z + s * ((k >> 2) & 1)});
  return {{"id", id}, {"vertices", v}};
}

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
  const json parts = {cube("frame", 0, 0, 0, 10),          cube("lid, top", 0, 0, lid_z, 10),
                      cube("bushing \"A\"", 9.5, 2, 2, 4), cube("pin", -1.95, 4, 4, 2),
                      cube("bolt", 40, 0, 0, 2),           ell,
                      cube("block", 107, 1.5, 0.5, 1)};
  return write_temp(name, json{{"units", "mm"}, {"tolerance", 0.1}, {"parts", parts}}.dump());
}

// A path of this test process's own: other test processes (sanitizer builds,
// worktrees) may run these tests at the same time.
std::string tmp(const std::string& name) {
  const std::string p = testing::TempDir() + "pdcheck" + std::to_string(getpid()) + "_" + name;
  std::remove(p.c_str());
  return p;
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
    x.baseline = tmp("exports_r1.json");
    EXPECT_EQ(pdcheck(scene("exports_s1.json", 10.0) + " -q -o " + x.baseline).code, 1);
    x.suppressions = suppressions_file();
    x.args = " -q --baseline " + x.baseline + " --suppressions " + x.suppressions;
    return x;
  }();
  return r;
}

/// Every entry of a BCF zip, in order (unzip -Z1), and its files unpacked in `dir`.
std::vector<std::string> unpack_bcf(const std::string& bcf, const std::string& dir) {
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
std::vector<std::string> check_bcf(const std::string& bcf, const std::string& dir) {
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

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// A number as the JSON report's text has it.
std::string number_text(const json& j) {
  return j.dump();
}

}  // namespace

// In process: a hand-made run whose ids need quoting, rows parsed back.
TEST(Exports, CsvQuotesIdsAsRfc4180Says) {
  pd::RunResult run;
  for (const std::string id : {"plain", "comma, id", "quote \"q\"", "line\nbreak", "far"}) {
    pd::Part p;
    p.id = id;
    p.source = "inline";
    run.parts.push_back(p);
  }
  auto pair = [&](int a, int b, pd::Status s, double depth) {
    pd::PairResult r;
    r.a = a;
    r.b = b;
    r.status = s;
    r.depth = depth;
    r.margin = 0.1 - depth;
    if (s == pd::Status::kError) r.error = "worker crashed, signal 11";
    return r;
  };
  run.pairs = {pair(0, 1, pd::Status::kInterference, 0.3), pair(1, 2, pd::Status::kSeparated, 0.0),
               pair(2, 3, pd::Status::kFalsePositive, 0.1 / 3), pair(0, 4, pd::Status::kError, 0)};
  run.pairs[0].at = pd::Vec3(1.0 / 3, -2.5e-7, 1e300);
  pd::ReportContext ctx;
  ctx.scene_path = "scene.json";
  ctx.units = "mm";
  ctx.tolerance = 0.1;
  pd::ReviewOptions opt;
  opt.tolerance = 0.1;
  const pd::Review review = pd::review_run(run, opt, true);
  const std::string csv = pd::render_csv({ctx, run, review, opt});
  std::string error;
  const Rows rows = parse_csv(csv, error);
  ASSERT_EQ(error, "") << csv;
  ASSERT_EQ(rows.size(), 4u) << csv;  // the header, and every pair but the separated one
  const std::vector<std::string> header = {
      "a",    "b",    "fingerprint", "status", "depth",          "tolerance",   "margin", "units",
      "at_x", "at_y", "at_z",        "group",  "baseline_state", "suppression", "message"};
  EXPECT_EQ(rows[0], header);
  for (const auto& r : rows) EXPECT_EQ(r.size(), header.size());
  EXPECT_EQ(rows[1][0], "plain");
  EXPECT_EQ(rows[1][1], "comma, id");
  EXPECT_EQ(rows[1][2], pd::pair_fingerprint("plain", "comma, id"));
  EXPECT_EQ(rows[1][3], "interference");
  // Numbers read back to the same doubles.
  EXPECT_EQ(std::stod(rows[1][4]), 0.3);
  EXPECT_EQ(std::stod(rows[1][6]), 0.1 - 0.3);
  EXPECT_EQ(std::stod(rows[1][8]), 1.0 / 3);
  EXPECT_EQ(std::stod(rows[1][9]), -2.5e-7);
  EXPECT_EQ(std::stod(rows[1][10]), 1e300);
  EXPECT_EQ(rows[2][0], "quote \"q\"");
  EXPECT_EQ(rows[2][1], "line\nbreak");
  EXPECT_EQ(std::stod(rows[2][4]), 0.1 / 3);
  EXPECT_EQ(rows[2][8], "");  // no `at`: empty, not invented
  EXPECT_EQ(rows[3][3], "error");
  EXPECT_EQ(rows[3][4], "");  // an error has no depth or margin
  EXPECT_EQ(rows[3][6], "");
  EXPECT_EQ(rows[3][14], "plain / far: error: worker crashed, signal 11");
  // Quoted exactly where needed.
  EXPECT_NE(csv.find("\r\nplain,\"comma, id\","), std::string::npos) << csv;
  EXPECT_NE(csv.find("\r\n\"quote \"\"q\"\"\",\"line\nbreak\","), std::string::npos) << csv;
}

TEST(Exports, BcfGuidsAreStableVersion8Uuids) {
  const std::regex uuid("[a-f0-9]{8}-[a-f0-9]{4}-8[a-f0-9]{3}-[89ab][a-f0-9]{3}-[a-f0-9]{12}");
  std::set<std::string> seen;
  for (const std::string& key :
       std::vector<std::string>{"", "a", "b", pd::pair_fingerprint("frame", "lid")})
    for (const std::string kind : {"topic", "viewpoint"}) {
      const std::string g = pd::bcf_guid(kind, key);
      EXPECT_TRUE(std::regex_match(g, uuid)) << g;
      EXPECT_EQ(g, pd::bcf_guid(kind, key));
      EXPECT_TRUE(seen.insert(g).second) << kind << " " << key;
    }
}

TEST(Exports, CameraLooksAcrossTheDepthAtTheFinding) {
  const pd::Aabb a{pd::Vec3(0, 0, 0), pd::Vec3(10, 10, 10)};
  const pd::Aabb b{pd::Vec3(8, 2, 2), pd::Vec3(12, 6, 6)};  // the smaller part
  const double fov = pd::tol::kBcfFieldOfView * M_PI / 180.0;
  for (const pd::Vec3& n :
       std::vector<pd::Vec3>{pd::Vec3::UnitZ(), pd::Vec3::UnitX(), pd::Vec3(1, 1, -1).normalized(),
                             pd::Vec3(0.3, -0.2, 0.9).normalized()}) {
    const pd::ViewTarget t = pd::view_target(pd::Vec3(9, 4, 4), a, b);
    EXPECT_TRUE(t.at);
    EXPECT_EQ(t.centre, pd::Vec3(9, 4, 4));
    EXPECT_NEAR(t.radius, 0.5 * std::sqrt(48.0), 1e-12);  // half the smaller box's diagonal
    const pd::PerspectiveCamera c = pd::camera_on(t, n);
    EXPECT_NEAR(c.direction.norm(), 1.0, 1e-12);
    EXPECT_NEAR(c.up.norm(), 1.0, 1e-12);
    EXPECT_NEAR(c.direction.dot(c.up), 0.0, 1e-12);
    // The camera looks at the centre, and the ball just fills the vertical view.
    const pd::Vec3 to = t.centre - c.viewpoint;
    EXPECT_NEAR(to.normalized().dot(c.direction), 1.0, 1e-12);
    EXPECT_NEAR(t.radius / to.norm(), std::sin(fov / 2), 1e-12);
    // Across the depth: the depth shows as a length, not a point.
    EXPECT_LT(std::abs(c.direction.dot(n)), 0.9) << n.transpose();
    EXPECT_GT(c.field_of_view, 0.0);
    EXPECT_LT(c.field_of_view, 180.0);
  }
  // Depth along z (a lid on a frame): a level view, z up.
  const pd::PerspectiveCamera level =
      pd::camera_on(pd::view_target(pd::Vec3(1, 1, 1), a, b), pd::Vec3::UnitZ());
  EXPECT_NEAR(level.direction.z(), 0.0, 1e-12);
  EXPECT_NEAR(level.up.z(), 1.0, 1e-12);
  // Without `at`: the centre of the boxes' overlap; boxes apart: between them.
  const pd::ViewTarget o = pd::view_target(std::nullopt, a, b);
  EXPECT_FALSE(o.at);
  EXPECT_EQ(o.centre, pd::Vec3(9, 4, 4));
  const pd::Aabb far{pd::Vec3(30, 0, 0), pd::Vec3(31, 1, 1)};
  const pd::ViewTarget m = pd::view_target(std::nullopt, a, far);
  EXPECT_EQ(m.centre, pd::Vec3(0.5 * (5 + 30.5), 5 * 0.5 + 0.25, 5 * 0.5 + 0.25));
  EXPECT_GE(m.radius, 0.5 * (pd::Vec3(5, 5, 5) - pd::Vec3(30.5, 0.5, 0.5)).norm());
}

// In process: every status through the BCF writer, each file valid; the
// topics are exactly the pairs that need a person.
TEST(Exports, EveryStatusGivesAValidBcf) {
  pd::RunResult run;
  for (const std::string id : {"a <&>", "b", "c", "d", "e", "f", "g"}) {
    pd::Part p;
    p.id = id;
    p.source = "inline";
    const int k = static_cast<int>(run.parts.size());
    p.box = {pd::Vec3(3.0 * k, 0, 0), pd::Vec3(3.0 * k + 4, 1, 1)};
    run.parts.push_back(p);
  }
  const pd::Status statuses[] = {pd::Status::kSeparated,    pd::Status::kFalsePositive,
                                 pd::Status::kInterference, pd::Status::kClearanceViolation,
                                 pd::Status::kUndecided,    pd::Status::kError};
  for (int k = 0; k < 6; ++k) {
    pd::PairResult r;
    r.a = k;
    r.b = k + 1;
    r.status = statuses[k];
    r.depth = k == 3 ? 0.0 : 0.02 * k;
    r.margin = 0.1 - r.depth;
    r.direction = pd::Vec3(0, 0, k % 2 ? 1 : -1);
    if (r.status == pd::Status::kClearanceViolation) {
      r.clearance_min = 0.5;
      r.distance = 0.2;
    }
    if (r.status == pd::Status::kUndecided) {
      r.depth_bounds = std::array<double, 2>{0.05, 0.2};
      r.reason = "work box exhausted";
      r.depth_source = "thickness";
      r.at = pd::Vec3(13.5, 0.5, 0.5);
    }
    if (r.status == pd::Status::kError) r.error = "worker timed out";
    run.pairs.push_back(r);
  }
  pd::ReportContext ctx;
  ctx.scene_path = "scene.json";
  ctx.units = "in";
  ctx.tolerance = 0.1;
  pd::ReviewOptions opt;
  opt.tolerance = 0.1;
  const pd::Review review = pd::review_run(run, opt, true);
  const std::string path = tmp("exports_statuses.bcf");
  std::ofstream(path, std::ios::binary) << pd::render_bcf({ctx, run, review, opt});
  const std::string dir = tmp("exports_statuses");
  const std::vector<std::string> topics = check_bcf(path, dir);
  // The interference (c, d) and the clearance violation (d, e) both move d
  // along −z: one finding group, one topic keyed by the group's id, its
  // deepest member (the interference) first. Then the undecided and the error.
  ASSERT_EQ(review.groups.groups.size(), 1u);
  const pd::FindingGroup& group = review.groups.groups[0];
  EXPECT_EQ(group.members, (std::vector<size_t>{2, 3}));
  std::vector<std::string> want{pd::bcf_guid("topic", group.id)};
  for (int k = 4; k < 6; ++k) want.push_back(pd::bcf_guid("topic", review.pairs[k].fingerprint));
  EXPECT_EQ(topics, want);
  if (topics.size() != 3) return;
  for (const auto& [k, type] : std::vector<std::pair<int, std::string>>{
           {0, "Interference"}, {1, "Undecided"}, {2, "Not checked"}})
    EXPECT_NE(read_text(dir + "/" + topics[k] + "/markup.bcf").find("TopicType=\"" + type + "\""),
              std::string::npos)
        << type;
  const std::string grouped = read_text(dir + "/" + topics[0] + "/markup.bcf");
  EXPECT_NE(grouped.find("(and 1 more)"), std::string::npos) << grouped;
  EXPECT_NE(grouped.find("<Label>clearance_violation</Label>"), std::string::npos) << grouped;
  EXPECT_NE(grouped.find("group " + group.id), std::string::npos) << grouped;
  // The undecided pair has an `at`: its line starts there, in metres (inches * 0.0254).
  const std::string v = read_text(dir + "/" + topics[1] + "/viewpoint.bcfv");
  EXPECT_NE(v.find("<StartPoint>\n        <X>" + number_text(13.5 * (25.4 / 1000.0)) + "</X>"),
            std::string::npos)
      << v;
  EXPECT_NE(read_text(dir + "/" + topics[0] + "/viewpoint.bcfv")
                .find("<AuthoringToolId>c</AuthoringToolId>"),
            std::string::npos);
}

// libzip dates entries through localtime(): the bytes must not depend on the zone.
TEST(Exports, ZipBytesDoNotDependOnTheTimeZone) {
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
  const std::string path = tmp("exports_tz.zip");
  std::ofstream(path, std::ios::binary) << first;
  const CliResult l = shell("unzip -l " + path);
  EXPECT_EQ(l.code, 0) << l.err;
  EXPECT_NE(l.out.find("1980-01-01 00:00   d/\n"), std::string::npos) << l.out;
  EXPECT_EQ(count(l.out, "1980-01-01 00:00"), 3u) << l.out;
}

// Through the binary: the CSV's rows are the report's non-separated pairs,
// field for field; the BCF validates and holds a topic per finding that needs
// a person; a second run in another time zone writes the same bytes.
TEST(Exports, CsvAndBcfMatchTheReport) {
  const Runs& base = runs();
  const std::string report = tmp("exports_r2.json"), csv = tmp("exports.csv"),
                    bcf = tmp("exports.bcf");
  const CliResult r = pdcheck(scene("exports_s2.json", 9.0) + base.args + " -o " + report +
                              " --csv " + csv + " --bcf " + bcf);
  ASSERT_EQ(r.code, 1) << r.err;
  const json rep = read_json(report);

  std::string error;
  const Rows rows = parse_csv(read_text(csv), error);
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

  const std::string dir = tmp("exports_bcf");
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
  EXPECT_EQ(count(v_lid, "<OriginatingSystem>pdcheck</OriginatingSystem>"),
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
  EXPECT_EQ(count(v_ell, "<Line>"), 1u);

  // The same run again, in another time zone: the same bytes.
  const std::string csv2 = tmp("exports2.csv"), bcf2 = tmp("exports2.bcf");
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
  const std::string csv = tmp("exports_full.csv"), bcf = tmp("exports_full.bcf");
  ASSERT_EQ(pdcheck(s + base.args + " -o /dev/null --csv " + csv + " --bcf " + bcf).code, 1);
  std::string shards;
  for (int k = 1; k <= 3; ++k) {
    const std::string out = tmp("exports_shard" + std::to_string(k) + ".json");
    const CliResult r = pdcheck(s + " -q --shard " + std::to_string(k) + "/3 -o " + out);
    ASSERT_NE(r.code, 2) << r.err;
    shards += " " + out;
  }
  const std::string mcsv = tmp("exports_merged.csv"), mbcf = tmp("exports_merged.bcf");
  const CliResult m =
      pdcheck("merge" + shards + base.args + " -o /dev/null --csv " + mcsv + " --bcf " + mbcf);
  ASSERT_EQ(m.code, 1) << m.err;
  EXPECT_EQ(read_text(mcsv), read_text(csv));
  EXPECT_TRUE(read_text(mbcf) == read_text(bcf)) << "the merged BCF differs from the run's";
  EXPECT_EQ(check_bcf(mbcf, tmp("exports_merged_bcf")).size(), 3u);

  const CliResult refused = pdcheck(s + " -q --shard 1/3 -o /dev/null --bcf " + tmp("x.bcf"));
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
