#include "batch/pair_tolerance.h"

#include <cstdio>

namespace pd {

namespace {

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

// One part's share of the band: its concave sag near the region, and the clause
// saying which feature gives it.
struct Share {
  double sag = 0.0;
  bool declared = false;
  std::string clause;
};

Share share(const Part& p, const Aabb& region, const std::string& units) {
  Share s;
  const PartSag& sag = *p.sag;
  if (sag.declared) {
    s.sag = *sag.declared;
    s.declared = true;
    s.clause = p.id + ": declared sag " + number(s.sag) + " " + units;
    return s;
  }
  const LocalSag near = sag_near(sag.measured, region);
  s.sag = near.concave;
  if (near.concave_feature < 0) {
    s.clause = p.id + ": no concave tessellated surface there";
    return s;
  }
  const SagFeature& f = sag.measured.features[near.concave_feature];
  s.clause = p.id + ": " + (f.convex > 0 ? "saddle" : "bore") + " r " + number(f.radius) + " " +
             units + ", " + std::to_string(f.segments) + " segments, sag " + number(f.concave) +
             " " + units;
  return s;
}

}  // namespace

Aabb meeting_region(const Part& a, const Part& b) {
  const Vec3 lo = a.box.lo.cwiseMax(b.box.lo), hi = a.box.hi.cwiseMin(b.box.hi);
  return {lo.cwiseMin(hi), lo.cwiseMax(hi)};
}

PairTolerance pair_tolerance(const Part& a, const Part& b, const AutoTolerance& t,
                             const std::string& units) {
  const Aabb region = meeting_region(a, b);
  const Share sa = share(a, region, units), sb = share(b, region, units);
  const double ra = a.sag->measured.resolution, rb = b.sag->measured.resolution;
  PairTolerance out;
  out.value = t.band(sa.sag, sb.sag, ra, rb);
  out.source = sa.declared || sb.declared ? "declared" : "measured";
  out.basis = sa.clause + "; " + sb.clause + "; coordinate steps " + number(ra) + " + " +
              number(rb) + " " + units;
  const double unclamped = AutoTolerance{}.band(sa.sag, sb.sag, ra, rb);
  if (out.value > unclamped) out.basis += "; raised to the scene's min";
  if (out.value < unclamped) out.basis += "; lowered to the scene's max";
  return out;
}

}  // namespace pd
