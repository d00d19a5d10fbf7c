// `tolerance: auto`, one pair's band (batch/pair_tolerance.h): where the parts
// can meet, the concave sags of the features there (a declared `sag` instead)
// plus both coordinate steps, with the margin and the scene's clamps, and a
// basis that names what it rests on.
#include <gtest/gtest.h>

#include "batch/pair_tolerance.h"
#include "tolerances.h"

using namespace pd;

namespace {

// A part of box [lo, hi] with coordinate step `step` and, when `concave` > 0,
// one bore-like feature of that sag filling the box.
Part part(const std::string& id, const Vec3& lo, const Vec3& hi, double step, double concave) {
  Part p;
  p.id = id;
  p.box = {lo, hi};
  PartSag sag;
  sag.measured.resolution = step;
  if (concave > 0) {
    SagFeature f;
    f.box = {lo, hi};
    f.concave = concave;
    f.radius = 5;
    f.segments = 32;
    f.facets = 64;
    sag.measured.features.push_back(f);
    sag.measured.concave = concave;
  }
  p.sag = sag;
  return p;
}

double band(double sa, double sb, double ra, double rb) {
  return (sa + sb + ra + rb) * (1 + tol::kAutoToleranceMargin);
}

}  // namespace

TEST(PairTolerance, TheMeetingRegionIsTheOverlapOrTheGap) {
  const Part a = part("a", Vec3(0, 0, 0), Vec3(2, 2, 2), 0, 0);
  const Part b = part("b", Vec3(1, 1, 1), Vec3(3, 3, 3), 0, 0);
  const Aabb overlap = meeting_region(a, b);
  EXPECT_EQ(overlap.lo, Vec3(1, 1, 1));
  EXPECT_EQ(overlap.hi, Vec3(2, 2, 2));
  const Part far = part("far", Vec3(5, 0, 0), Vec3(6, 2, 2), 0, 0);
  const Aabb gap = meeting_region(a, far);  // spans the gap along x
  EXPECT_EQ(gap.lo, Vec3(2, 0, 0));
  EXPECT_EQ(gap.hi, Vec3(5, 2, 2));
}

TEST(PairTolerance, MeasuredSagsAndStepsWithTheMarginNamed) {
  const Part a = part("bore", Vec3(0, 0, 0), Vec3(2, 2, 2), 1e-6, 0.02);
  const Part b = part("block", Vec3(1, 1, 1), Vec3(3, 3, 3), 2e-6, 0);
  const PairTolerance t = pair_tolerance(a, b, AutoTolerance{}, "mm");
  EXPECT_DOUBLE_EQ(t.value, band(0.02, 0, 1e-6, 2e-6));
  EXPECT_EQ(t.source, "measured");
  EXPECT_EQ(t.basis,
            "bore: bore r 5 mm, 32 segments, sag 0.02 mm; block: no concave tessellated surface "
            "there; coordinate steps 1e-06 + 2e-06 mm");
  ASSERT_TRUE(t.at_contact);
  ASSERT_TRUE(t.gap_at);
  // At the contact the sags of the patches there count: the feature has none
  // (no facets by place), so the steps alone.
  EXPECT_DOUBLE_EQ(t.at_contact(Vec3(1.5, 1.5, 1.5), 0.1).value, band(0, 0, 1e-6, 2e-6));
}

TEST(PairTolerance, FlatPartsGetTheFloorOfTheirCoordinateSteps) {
  // Measured sag 0 on both: the band is the steps with the margin, never 0,
  // and the basis says it is the floor.
  const Part a = part("plate", Vec3(0, 0, 0), Vec3(2, 2, 2), 1e-6, 0);
  const Part b = part("block", Vec3(1, 1, 1), Vec3(3, 3, 3), 2e-6, 0);
  const PairTolerance t = pair_tolerance(a, b, AutoTolerance{}, "mm");
  EXPECT_DOUBLE_EQ(t.value, band(0, 0, 1e-6, 2e-6));
  EXPECT_GT(t.value, 0.0);
  EXPECT_EQ(t.basis,
            "plate: no concave tessellated surface there; block: no concave tessellated surface "
            "there; coordinate steps 1e-06 + 2e-06 mm (flat there: the band's floor, the "
            "coordinates' rounding)");
  // One tessellated part: its sag, no floor said.
  const Part bore = part("bore", Vec3(0, 0, 0), Vec3(2, 2, 2), 1e-6, 0.02);
  EXPECT_EQ(pair_tolerance(bore, b, AutoTolerance{}, "mm").basis.find("floor"), std::string::npos);
}

TEST(PairTolerance, ADeclaredSagReplacesTheMeasuredOne) {
  const Part a = part("bore", Vec3(0, 0, 0), Vec3(2, 2, 2), 1e-6, 0.02);
  Part b = part("block", Vec3(1, 1, 1), Vec3(3, 3, 3), 2e-6, 0);
  b.sag->declared = 0.01;
  const PairTolerance t = pair_tolerance(a, b, AutoTolerance{}, "in");
  EXPECT_DOUBLE_EQ(t.value, band(0.02, 0.01, 1e-6, 2e-6));
  EXPECT_EQ(t.source, "declared");
  EXPECT_NE(t.basis.find("block: declared sag 0.01 in"), std::string::npos) << t.basis;
}

TEST(PairTolerance, AFeatureAwayFromTheMeetingRegionDoesNotCount) {
  const Part a = part("bore", Vec3(0, 0, 0), Vec3(2, 2, 2), 0, 0.02);
  Part moved = a;
  moved.sag->measured.features[0].box = {Vec3(10, 10, 10), Vec3(11, 11, 11)};
  const Part b = part("block", Vec3(1, 1, 1), Vec3(3, 3, 3), 0, 0);
  EXPECT_DOUBLE_EQ(pair_tolerance(moved, b, AutoTolerance{}, "mm").value, 0.0);
  EXPECT_GT(pair_tolerance(a, b, AutoTolerance{}, "mm").value, 0.0);
}

TEST(PairTolerance, TheScenesClampsAreNamed) {
  const Part a = part("bore", Vec3(0, 0, 0), Vec3(2, 2, 2), 0, 0.02);
  const Part b = part("block", Vec3(1, 1, 1), Vec3(3, 3, 3), 0, 0);
  AutoTolerance low;
  low.min = 1.0;
  const PairTolerance raised = pair_tolerance(a, b, low, "mm");
  EXPECT_EQ(raised.value, 1.0);
  EXPECT_NE(raised.basis.find("raised to the scene's min"), std::string::npos) << raised.basis;
  AutoTolerance high;
  high.max = 0.001;
  const PairTolerance lowered = pair_tolerance(a, b, high, "mm");
  EXPECT_EQ(lowered.value, 0.001);
  EXPECT_NE(lowered.basis.find("lowered to the scene's max"), std::string::npos) << lowered.basis;
}
