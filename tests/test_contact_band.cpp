// Tolerance auto at the contact (issue 27): the band of the features where a
// pair's depth is, not of every feature where its boxes meet; a pair decided
// again against it; the gap band of clearance checks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "batch/contact_band.h"
#include "batch/pair_solve.h"
#include "batch/pair_tolerance.h"
#include "cli_support.h"
#include "corpus/cad_shapes.h"
#include "sag_part.h"
#include "scratch_dir.h"
#include "stl_file.h"
#include "tolerances.h"

using namespace pd;
using pd_test::chord_sag;
using pd_test::sag_part;

namespace {

const double kMargin = 1 + tol::kAutoToleranceMargin;

// A flanged bushing: a fine bore (128 segments, r 5, z 0..10) and, 3 mm out
// from it, a coarse concave fillet (two 45° chords of r 2) between the flange
// top (z 2) and the hub wall (r 8). The fillet, flange top and hub wall are one
// smooth region whose box holds the bore.
Mesh flanged_bushing() {
  const double c = 2 / std::sqrt(2.0);
  return shapes::revolution(
      {{5, 0}, {16, 0}, {16, 2}, {10, 2}, {10 - c, 4 - c}, {8, 4}, {8, 10}, {5, 10}}, 128);
}

struct Fixture {
  Part bushing = sag_part("bushing", flanged_bushing());
  Part pin = sag_part("pin", shapes::revolution({{0, -5}, {5, -5}, {5, 15}, {0, 15}}, 96));
  Vec3 on_bore{4.999, 0.0, 5.0};  // where the pin meets the bore
};

// A pair decided against `wide` as the refinement decides a thickness.
PairResult thickness_pair(Status s, double lower, double upper, const Vec3& at,
                          const PairTolerance& wide) {
  PairResult r;
  r.status = s;
  r.depth_source = "thickness";
  r.depth = lower;
  r.depth_bounds = {{lower, upper}};
  r.at = at;
  r.tolerance = wide.value;
  r.tolerance_source = wide.source;
  r.tolerance_basis = wide.basis;
  return r;
}

}  // namespace

TEST(ContactBand, PatchesLieAlongTheSurfaceNotInTheFeaturesBox) {
  const Fixture f;
  const TessellationSag& s = f.bushing.sag->measured;
  const LocalSag boxes = sag_near(s, meeting_region(f.bushing, f.pin));
  EXPECT_GT(boxes.concave, 0.1);  // the fillet's region box holds the bore
  const LocalSag at = sag_at(s, f.on_bore, 0.01);
  EXPECT_NEAR(at.concave, chord_sag(128, 5), 0.1 * chord_sag(128, 5));
  ASSERT_GE(at.concave_feature, 0);
  EXPECT_EQ(s.features[at.concave_feature].segments, 128);
  EXPECT_EQ(sag_at(s, {0, 0, 50}, 0.01).concave_feature, -1);  // nothing there
  // On the fillet itself, its own sag.
  EXPECT_GT(sag_at(s, {9, 0, 3}, 0.1).concave, 0.1);
}

TEST(ContactBand, TheBandAtTheContactComesFromTheBoreOnly) {
  const Fixture f;
  const PairTolerance wide = pair_tolerance(f.bushing, f.pin, {}, "mm");
  EXPECT_GT(wide.value, 0.1 * kMargin);
  EXPECT_NE(wide.basis.find("saddle"), std::string::npos) << wide.basis;
  ASSERT_TRUE(wide.at_contact);
  const PairTolerance local = wide.at_contact(f.on_bore, contact_reach(0.001, wide.value));
  const double bore = chord_sag(128, 5) * kMargin;
  EXPECT_NEAR(local.value, bore, 0.1 * bore);
  EXPECT_EQ(local.source, "measured");
  EXPECT_EQ(local.basis.rfind("bushing: bore r 5 mm, 128 segments, sag 0.00151 mm; pin: no concave "
                              "tessellated surface there; coordinate steps",
                              0),
            0u)
      << local.basis;
  EXPECT_EQ(local.basis.find("saddle"), std::string::npos) << local.basis;
}

TEST(ContactBand, APairIsDecidedAgainAtItsContact) {
  const Fixture f;
  const PairTolerance wide = pair_tolerance(f.bushing, f.pin, {}, "mm");
  const double local = wide.at_contact(f.on_bore, 0.2).value;
  // An artefact of the bore: a false positive against the bore's band.
  PairResult fp = thickness_pair(Status::kFalsePositive, 0.0005, 0.0012, f.on_bore, wide);
  decide_at_contact(fp, wide);
  EXPECT_EQ(fp.status, Status::kFalsePositive);
  EXPECT_DOUBLE_EQ(*fp.tolerance, local);
  EXPECT_DOUBLE_EQ(fp.margin, local - 0.0005);
  EXPECT_NE(fp.tolerance_basis.find("128 segments"), std::string::npos);
  // 0.05 mm at the fine bore hides under the fillet's band, not under the bore's.
  PairResult deep = thickness_pair(Status::kFalsePositive, 0.05, 0.051, f.on_bore, wide);
  decide_at_contact(deep, wide);
  EXPECT_EQ(deep.status, Status::kInterference);
  EXPECT_DOUBLE_EQ(*deep.tolerance, local);
  // An undecided bracket above the bore's band is decided.
  PairResult open = thickness_pair(Status::kUndecided, 0.02, 0.3, f.on_bore, wide);
  open.reason = "work budget reached";
  open.confirmed = false;
  decide_at_contact(open, wide);
  EXPECT_EQ(open.status, Status::kInterference);
  EXPECT_TRUE(open.reason.empty());
  EXPECT_EQ(open.confirmed, true);
  // A bracket around the bore's band: the wide band's decision stands, said so.
  PairResult straddle = thickness_pair(Status::kFalsePositive, 0.0005, 0.05, f.on_bore, wide);
  decide_at_contact(straddle, wide);
  EXPECT_EQ(straddle.status, Status::kFalsePositive);
  EXPECT_DOUBLE_EQ(*straddle.tolerance, wide.value);
  EXPECT_NE(straddle.tolerance_basis.find("does not decide against the band at the contact"),
            std::string::npos)
      << straddle.tolerance_basis;
  // A hull's depth (its witness need not be on a surface) keeps the wide band.
  PairResult hull = thickness_pair(Status::kFalsePositive, 0.05, 0.05, f.on_bore, wide);
  hull.depth_source = "hull";
  decide_at_contact(hull, wide);
  EXPECT_EQ(hull.status, Status::kFalsePositive);
  EXPECT_DOUBLE_EQ(*hull.tolerance, wide.value);
}

TEST(ContactBand, DecidingTwiceIsDecidingOnce) {
  // The refinement cache and --reuse store decided pairs; noting them again
  // (note_pair_tolerance) must give the same result.
  const Fixture f;
  PairChecks c;
  c.tolerance = pair_tolerance(f.bushing, f.pin, {}, "mm");
  for (const auto& [lower, upper] : {std::pair{0.0005, 0.0012}, {0.05, 0.051}, {0.0005, 0.05}}) {
    PairResult r = thickness_pair(Status::kFalsePositive, lower, upper, f.on_bore, *c.tolerance);
    note_pair_tolerance(r, c);
    PairResult again = r;
    note_pair_tolerance(again, c);
    EXPECT_EQ(again.status, r.status) << lower;
    EXPECT_EQ(again.tolerance, r.tolerance) << lower;
    EXPECT_EQ(again.tolerance_basis, r.tolerance_basis) << lower;
  }
}

TEST(ContactBand, StatusAgainstABand) {
  EXPECT_EQ(status_against(0.2, 0.3, 0.1, 0.0), Status::kInterference);
  EXPECT_EQ(status_against(0.0, 0.1, 0.1, 0.0), Status::kFalsePositive);
  EXPECT_EQ(status_against(0.05, 0.15, 0.1, 0.0), Status::kUndecided);
  EXPECT_EQ(status_against(0.05, 0.1 + 1e-12, 0.1, 1e-11), Status::kFalsePositive);
}

TEST(ContactBand, TheGapBandIsTheConvexSagsWhereTheGapIs) {
  // A 48-segment pin beside the bushing's bore wall: the pin's convex sag
  // counts, the bore (concave) adds none.
  const Fixture f;
  const Part pin48 =
      sag_part("pin", shapes::revolution({{0, -5}, {4.9, -5}, {4.9, 15}, {0, 15}}, 48));
  const PairTolerance wide = pair_tolerance(f.bushing, pin48, {}, "mm");
  ASSERT_TRUE(wide.gap_at);
  const GapBand g = wide.gap_at({4.95, 0, 5}, 0.1);
  const double pin = chord_sag(48, 4.9) * kMargin;
  EXPECT_NEAR(g.value, pin, 0.1 * pin);
  EXPECT_NE(g.basis.find("pin: pin r 4.9 mm, 48 segments"), std::string::npos) << g.basis;
  EXPECT_NE(g.basis.find("bushing: no convex tessellated surface there"), std::string::npos)
      << g.basis;
  // Recorded on a separated pair with a distance; a declared sag replaces both signs.
  PairResult r;
  r.status = Status::kSeparated;
  r.distance = 0.1;
  note_gap_band(r, &wide, Vec3(4.95, 0, 5));
  ASSERT_TRUE(r.gap_band);
  EXPECT_DOUBLE_EQ(*r.gap_band, g.value);
  Part declared = pin48;
  declared.sag->declared = 0.02;
  EXPECT_NE(gap_band(f.bushing, declared, "mm", {4.95, 0, 5}, 0.1).basis.find("declared sag 0.02"),
            std::string::npos);
  PairResult none;
  none.distance = 0.1;
  note_gap_band(none, nullptr, Vec3(4.95, 0, 5));  // a fixed tolerance: no gap band
  EXPECT_FALSE(none.gap_band);
}

// ---- Through the binary, on float32 STL files (tests/stl_file.h) ----

namespace {

std::string fresh_dir(const std::string& name) {
  return pd_test::scratch_dir("contact_band", name).string() + "/";
}

nlohmann::json only_pair(const test::CliResult& r) {
  const auto rep = nlohmann::json::parse(r.out);
  EXPECT_EQ(rep["pairs"].size(), 1u) << r.err;
  return rep["pairs"].empty() ? nlohmann::json{} : rep["pairs"][0];
}

// pdcheck under tolerance auto on a bushing and a pin, written as float32 STL
// files in a fresh directory `name`.
test::CliResult check_bushing_and_pin(const std::string& name, const Mesh& bushing,
                                      const Mesh& pin) {
  const std::string d = fresh_dir(name);
  test::write_binary_stl(d + "bushing.stl", bushing);
  test::write_binary_stl(d + "pin.stl", pin);
  const std::string scene =
      test::write_temp("contact_band_" + name + ".json",
                       R"({"tolerance": "auto", "parts": [{"id": "bushing", "mesh": ")" + d +
                           R"(bushing.stl"}, {"id": "pin", "mesh": ")" + d + R"(pin.stl"}]})");
  return test::pdcheck(scene + " --no-cache -j 1");
}

}  // namespace

TEST(ContactBand, AFineBoreBesideACoarseFilletGetsTheBoresBand) {
  // The flanged bushing (bore 64 segments, sag 0.0060; fillet sag > 0.1) and a
  // 48-segment pin in its bore, touching: the pair's band is the bore's.
  const double c = 2 / std::sqrt(2.0);
  const test::CliResult r = check_bushing_and_pin(
      "fillet",
      shapes::revolution(
          {{5, 0}, {16, 0}, {16, 2}, {10, 2}, {10 - c, 4 - c}, {8, 4}, {8, 10}, {5, 10}}, 64),
      shapes::revolution({{0, -5}, {5, -5}, {5, 15}, {0, 15}}, 48));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto p = only_pair(r);
  EXPECT_EQ(p["status"], "false_positive");
  const double bore = chord_sag(64, 5) * kMargin;
  EXPECT_NEAR(p["tolerance"].get<double>(), bore, 0.1 * bore) << p.dump();
  const std::string basis = p["tolerance_basis"];
  EXPECT_EQ(basis.rfind("bushing: bore r 5 mm, 64 segments, sag 0.006", 0), 0u) << basis;
  EXPECT_EQ(basis.find("saddle"), std::string::npos) << basis;
  EXPECT_EQ(basis.find("does not decide"), std::string::npos) << basis;
}

TEST(ContactBand, AFineFloat32ContactFarFromTheOriginIsDecided) {
  // A 64-segment bore and a 48-segment pin of radius 5 at x = 35,000 mm in
  // float32 (steps 0.0039 mm): the band holds both steps, and the certified
  // bracket closes within it. The bore's chords cut 0.006 mm into the hole,
  // within the coordinates' resolution there (2 steps of each part, 0.0156
  // mm): touching.
  const Vec3 far(35000, 0, 0);
  const test::CliResult r = check_bushing_and_pin(
      "far", shapes::translated(shapes::revolution({{5, 0}, {8, 0}, {8, 10}, {5, 10}}, 64), far),
      shapes::translated(shapes::revolution({{0, -5}, {5, -5}, {5, 15}, {0, 15}}, 48), far));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto p = only_pair(r);
  const double step = 1.0 / 256;  // float32 at 32,768–65,536
  EXPECT_EQ(p["status"], "separated") << p.dump();
  EXPECT_LE(p["depth_bounds"][1].get<double>(), 4 * step) << p.dump();
  const double band = (chord_sag(64, 5) + 2 * step) * kMargin;
  EXPECT_NEAR(p["tolerance"].get<double>(), band, 0.1 * band) << p.dump();
  EXPECT_LE(p["depth_bounds"][1].get<double>(), p["tolerance"].get<double>());
  EXPECT_NE(p["tolerance_basis"].get<std::string>().find("coordinate steps 0.00391 + 0.00391 mm"),
            std::string::npos);
}

TEST(ContactBand, AClearanceIsCheckedAgainstTheGapBand) {
  // A 48-segment pin of radius 4.6 beside a block whose face is at x = 4.6 +
  // `gap` (the true gap), a facet (not a vertex) of the pin facing it: the
  // pin's convex sag, 4.6 (1 − cos(π/48)) = 0.0099 mm, shows as extra gap.
  // Clearance required: 0.105 mm. (A pin in a bore goes through the convex
  // pieces of the bore's decomposition, whose gap is the pieces'; a block keeps
  // the gap the meshes' own.)
  const std::string d = fresh_dir("clearance");
  test::write_binary_stl(d + "pin.stl",
                         shapes::revolution({{0, -5}, {4.6, -5}, {4.6, 15}, {0, 15}}, 48));
  const double half = M_PI / 48;
  const auto scene_with = [&](double gap, const std::string& tolerance) {
    test::write_binary_stl(d + "block.stl", shapes::box({4.6 + gap, -10, 0}, {10, 10, 10}));
    char transform[256];
    std::snprintf(transform, sizeof transform,
                  "[[%.17g,%.17g,0,0],[%.17g,%.17g,0,0],[0,0,1,0],[0,0,0,1]]", std::cos(half),
                  -std::sin(half), std::sin(half), std::cos(half));
    return test::write_temp(
        "contact_band_clearance.json",
        R"({"tolerance": )" + tolerance +
            R"(, "checks": {"clearance": {"min": 0.105}}, "parts": [{"id": "block", "mesh": ")" +
            d + R"(block.stl"}, {"id": "pin", "mesh": ")" + d + R"(pin.stl", "transform": )" +
            transform + "}]}");
  };
  const double pin_sag = chord_sag(48, 4.6);
  // True gap 0.09 (< 0.105): the mesh shows 0.0999; auto says how much of it
  // the tessellation can have made (the boxes of a pair farther apart than the
  // clearance are culled before any gap band is known).
  const auto pf = only_pair(test::pdcheck(scene_with(0.09, "0.01") + " --no-cache -j 1"));
  EXPECT_EQ(pf["status"], "clearance_violation") << pf.dump();
  EXPECT_NEAR(pf["clearance"]["distance"].get<double>(), 0.09 + pin_sag, 1e-5);
  EXPECT_FALSE(pf["clearance"].contains("gap_band"));
  const test::CliResult a = test::pdcheck(scene_with(0.09, R"("auto")") + " --no-cache -j 1");
  EXPECT_EQ(a.code, 1) << a.err;
  const auto pa = only_pair(a);
  EXPECT_EQ(pa["status"], "clearance_violation") << pa.dump();
  const double band = pa["clearance"]["gap_band"];
  EXPECT_NEAR(band, pin_sag * kMargin, 0.1 * pin_sag * kMargin);
  EXPECT_NE(pa["clearance"]["gap_basis"].get<std::string>().find("pin: pin r 4.6 mm, 48 segments"),
            std::string::npos)
      << pa.dump();
  EXPECT_NE(a.err.find(" - gap band "), std::string::npos) << a.err;
  // Touching (true gap 0): the mesh shows the pin's sag as a gap; auto says
  // it is a contact, and a contact is closer than any clearance.
  EXPECT_EQ(only_pair(test::pdcheck(scene_with(0.0, "0.01") + " --no-cache -j 1"))["status"],
            "clearance_violation");
  const test::CliResult touching = test::pdcheck(scene_with(0.0, R"("auto")") + " --no-cache -j 1");
  EXPECT_EQ(touching.code, 1) << touching.err;
  const auto pt = only_pair(touching);
  EXPECT_EQ(pt["status"], "clearance_violation") << pt.dump();
  EXPECT_LE(pt["clearance"]["distance"].get<double>(), pt["clearance"]["gap_band"].get<double>());
  EXPECT_NE(touching.err.find("touching, distance "), std::string::npos) << touching.err;
}
