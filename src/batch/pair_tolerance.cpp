#include "batch/pair_tolerance.h"

#include <cstdio>

#include "batch/pair_solve.h"
#include "tolerances.h"

namespace pd {

std::string band_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

namespace {

// One part's share of a band: its sag of one sign where the parts meet, and the
// clause saying which feature gives it.
struct Share {
  double sag = 0.0;
  bool declared = false;
  std::string clause;
};

enum class Sign { kConcave, kConvex };

Share share(const Part& p, const LocalSag& near, Sign sign, const std::string& units) {
  Share s;
  const PartSag& sag = *p.sag;
  if (sag.declared) {
    s.sag = *sag.declared;
    s.declared = true;
    s.clause = p.id + ": declared sag " + band_number(s.sag) + " " + units;
    return s;
  }
  const bool concave = sign == Sign::kConcave;
  const int k = concave ? near.concave_feature : near.convex_feature;
  s.sag = concave ? near.concave : near.convex;
  if (k < 0) {
    s.clause = p.id + ": no " + (concave ? "concave" : "convex") + " tessellated surface there";
    return s;
  }
  const SagFeature& f = sag.measured.features[k];
  const char* kind = f.convex > 0 && f.concave > 0 ? "saddle" : concave ? "bore" : "pin";
  s.clause = p.id + ": " + kind + " r " + band_number(f.radius) + " " + units + ", " +
             std::to_string(f.segments) + " segments, sag " + band_number(s.sag) + " " + units;
  return s;
}

PairTolerance band_of(const Part& a, const Part& b, const AutoTolerance& t,
                      const std::string& units, const LocalSag& near_a, const LocalSag& near_b) {
  const Share sa = share(a, near_a, Sign::kConcave, units);
  const Share sb = share(b, near_b, Sign::kConcave, units);
  const double ra = a.sag->measured.resolution, rb = b.sag->measured.resolution;
  PairTolerance out;
  out.value = t.band(sa.sag, sb.sag, ra, rb);
  out.source = sa.declared || sb.declared ? "declared" : "measured";
  out.basis = sa.clause + "; " + sb.clause + "; coordinate steps " + band_number(ra) + " + " +
              band_number(rb) + " " + units;
  // Flat where they meet: the mesh is the part, and a design contact
  // overlaps by no more than the coordinates' rounding (docs/numerics.md).
  if (sa.sag == 0 && sb.sag == 0 && !sa.declared && !sb.declared)
    out.basis += " (flat there: the band's floor, the coordinates' rounding)";
  const double unclamped = AutoTolerance{}.band(sa.sag, sb.sag, ra, rb);
  if (out.value > unclamped) out.basis += "; raised to the scene's min";
  if (out.value < unclamped) out.basis += "; lowered to the scene's max";
  out.pair_size = pair_size(a, b);
  return out;
}

}  // namespace

Aabb meeting_region(const Part& a, const Part& b) {
  const Vec3 lo = a.box.lo.cwiseMax(b.box.lo), hi = a.box.hi.cwiseMin(b.box.hi);
  return {lo.cwiseMin(hi), lo.cwiseMax(hi)};
}

PairTolerance pair_tolerance(const Part& a, const Part& b, const AutoTolerance& t,
                             const std::string& units) {
  const Aabb region = meeting_region(a, b);
  PairTolerance out =
      band_of(a, b, t, units, sag_near(a.sag->measured, region), sag_near(b.sag->measured, region));
  out.at_contact = [&a, &b, t, units](const Vec3& at, double reach) {
    return contact_tolerance(a, b, t, units, at, reach);
  };
  out.gap_at = [&a, &b, units](const Vec3& at, double reach) {
    return gap_band(a, b, units, at, reach);
  };
  return out;
}

PairTolerance contact_tolerance(const Part& a, const Part& b, const AutoTolerance& t,
                                const std::string& units, const Vec3& at, double reach) {
  return band_of(a, b, t, units, sag_at(a.sag->measured, at, reach),
                 sag_at(b.sag->measured, at, reach));
}

GapBand gap_band(const Part& a, const Part& b, const std::string& units, const Vec3& at,
                 double reach) {
  const Share sa = share(a, sag_at(a.sag->measured, at, reach), Sign::kConvex, units);
  const Share sb = share(b, sag_at(b.sag->measured, at, reach), Sign::kConvex, units);
  const double ra = a.sag->measured.resolution, rb = b.sag->measured.resolution;
  GapBand out;
  out.value = AutoTolerance{}.band(sa.sag, sb.sag, ra, rb);
  out.basis = sa.clause + "; " + sb.clause + "; coordinate steps " + band_number(ra) + " + " +
              band_number(rb) + " " + units;
  return out;
}

}  // namespace pd
