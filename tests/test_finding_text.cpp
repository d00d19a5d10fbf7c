// Every sentence a user reads about a pair (stderr, JUnit, SARIF, the HTML
// page) comes from finding_text: rendered here for every status and depth
// source and checked against the pair's numbers.
#include <gtest/gtest.h>

#include <regex>

#include "page_data.h"
#include "report/finding_text.h"
#include "report/report_json.h"
#include "report/write_html.h"

namespace pd {
namespace {

PairResult pair(Status status, const std::string& source) {
  PairResult r;
  r.a = 0;
  r.b = 1;
  r.status = status;
  r.depth_source = source;
  r.depth = status == Status::kInterference ? 0.3 : status == Status::kSeparated ? 0.0 : 0.02;
  r.margin = 0.05 - r.depth;
  r.direction = Vec3(0, 0, 1);
  r.method = "mlsl";
  if (source != "hull") r.hull_depth = 12.0;
  if (source != "hull" || status == Status::kUndecided)
    r.depth_bounds = {{r.depth, status == Status::kUndecided ? 0.4 : r.depth + 0.01}};
  if (status == Status::kUndecided) r.reason = "work budget reached";
  if (status == Status::kError) r.error = "worker crashed";
  if (status == Status::kClearanceViolation) r.clearance_min = 1.0, r.distance = 0.5;
  return r;
}

std::vector<Part> parts() {
  std::vector<Part> p(2);
  p[0].id = "plate";
  p[1].id = "bolt";
  return p;
}

TEST(FindingText, EverySentenceAgreesWithTheNumbers) {
  const Status statuses[] = {Status::kSeparated, Status::kFalsePositive,      Status::kInterference,
                             Status::kError,     Status::kClearanceViolation, Status::kUndecided};
  for (Status s : statuses)
    for (const std::string source :
         {"hull", "thickness", "surface", "vertex", "pieces", "mesh-test"}) {
      const PairResult r = pair(s, source);
      const std::string t = finding_text(r, parts(), PairReview{}, "mm", 0.05);
      const std::string what = std::string(status_name(s)) + " / " + source + ": " + t;
      EXPECT_EQ(t.rfind("plate / bolt: " + std::string(status_name(s)), 0), 0u) << what;
      // Only a convex pair's (hull) depth is a move that separates the pair.
      const bool claims_move = t.find("separates the pair") != std::string::npos ||
                               t.find("separating normal") != std::string::npos;
      const bool decided =
          s == Status::kSeparated || s == Status::kFalsePositive || s == Status::kInterference;
      if (decided) {
        EXPECT_EQ(claims_move, source == "hull") << what;
      } else if (s == Status::kUndecided) {
        EXPECT_FALSE(claims_move) << what;
      }
      if (s == Status::kInterference) {
        EXPECT_NE(t.find("0.3 mm > tolerance 0.05 mm"), t.npos) << what;
      }
      if (s == Status::kFalsePositive) {
        EXPECT_NE(t.find("0.02 mm <= tolerance 0.05 mm"), t.npos) << what;
      }
      if (s == Status::kUndecided) {
        EXPECT_NE(t.find("between 0.02 and 0.4 mm"), t.npos) << what;
        EXPECT_NE(t.find("work budget reached"), t.npos) << what;
        EXPECT_EQ(t.find(" > tolerance"), t.npos) << what;  // never called an interference
      }
      if (s == Status::kError) {
        EXPECT_NE(t.find("worker crashed"), t.npos) << what;
      }
      if (source == "thickness" && (s == Status::kFalsePositive || s == Status::kInterference)) {
        EXPECT_NE(t.find("overlap thickness"), t.npos) << what;
      }
      // A certified bracket is quoted with the numbers it holds.
      if (source != "hull" && s != Status::kError && s != Status::kSeparated &&
          s != Status::kClearanceViolation) {
        const auto [lo, hi] = *r.depth_bounds;
        EXPECT_NE(t.find(short_number(lo)), t.npos) << what;
        EXPECT_NE(t.find(short_number(hi)), t.npos) << what;
      }
    }
}

TEST(FindingText, AClearanceViolationSaysWhetherTheShortfallIsAGapAContactOrAnOverlap) {
  PairResult gap = pair(Status::kClearanceViolation, "hull");
  EXPECT_NE(finding_text(gap, parts(), PairReview{}, "mm", 0.05)
                .find(": distance 0.5 mm < required clearance 1 mm"),
            std::string::npos);
  PairResult touching = gap;
  touching.distance = 0.004, touching.gap_band = 0.01, touching.gap_basis = "bolt: r 4 mm";
  EXPECT_NE(finding_text(touching, parts(), PairReview{}, "mm", 0.05)
                .find(": touching, distance 0.004 mm <= gap band 0.01 mm (bolt: r 4 mm), closer "
                      "than the required clearance 1 mm"),
            std::string::npos);
  PairResult press = gap;
  press.distance.reset();
  press.depth = 0.02;
  EXPECT_NE(finding_text(press, parts(), PairReview{}, "mm", 0.05)
                .find(": overlapping, depth 0.02 mm <= tolerance 0.05 mm (a contact, not an "
                      "interference), closer than the required clearance 1 mm"),
            std::string::npos);
}

TEST(FindingText, TheHtmlPageShowsTheSameSentence) {
  const std::vector<Part> p = parts();
  nlohmann::ordered_json report = {{"scene", "s.json"},
                                   {"units", "mm"},
                                   {"tolerance", 0.05},
                                   {"summary", {{"undecided", 1}, {"false_positive", 1}}},
                                   {"pairs",
                                    {pair_json(pair(Status::kUndecided, "thickness"), p),
                                     pair_json(pair(Status::kFalsePositive, "thickness"), p)}}};
  const std::string page = render_html(report, p);
  const nlohmann::json data = page_data(page);
  ASSERT_EQ(data["findings"].size(), 2u);
  for (const auto& f : data["findings"]) {
    const Status s = f["status"] == "undecided" ? Status::kUndecided : Status::kFalsePositive;
    EXPECT_EQ(f["text"], finding_text(pair(s, "thickness"), p, PairReview{}, "mm", 0.05));
  }
}

}  // namespace
}  // namespace pd
