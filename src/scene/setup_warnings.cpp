#include "scene/setup_warnings.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tolerances.h"

namespace pd {

namespace {

std::string num(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", x + 0.0);  // no -0
  return buf;
}

// The units factors against millimetres: a file in `unit` read as mm (or the
// other way round) reads `factor` times too large (small).
struct UnitsFactor {
  double factor;
  const char* unit;
  const char* words;
};
constexpr UnitsFactor kUnitsFactors[] = {{25.4, "in", "inches"},
                                         {1000.0, "m", "metres"},
                                         {304.8, "ft", "feet"},
                                         {10.0, "cm", "centimetres"}};
constexpr UnitsFactor kMillimetres = {1.0, "mm", "millimetres"};

// The unit of `mm` millimetres, if one of kUnitsFactors or mm.
const UnitsFactor* unit_of(double mm) {
  if (std::abs(mm - 1.0) < 1e-6) return &kMillimetres;
  for (const UnitsFactor& u : kUnitsFactors)
    if (std::abs(mm / u.factor - 1.0) < 1e-6) return &u;
  return nullptr;
}
// Those a size alone can make credible: a 10 times larger or smaller part is
// ordinary in any assembly (a washer beside a housing), a cm file is rare.
constexpr int kSizeFactors = 3;

double size_of(const Aabb& b) {
  return (b.hi - b.lo).maxCoeff();
}

// The factor of kUnitsFactors (or 1/that) whose scale is nearest `ratio`'s
// (in logarithm), among the first `count`.
double nearest_factor(double ratio, int count) {
  double best = 1.0;
  for (int k = 0; k < count; ++k) {
    const double f = ratio >= 1 ? kUnitsFactors[k].factor : 1.0 / kUnitsFactors[k].factor;
    if (best == 1.0 || std::abs(std::log(ratio / f)) < std::abs(std::log(ratio / best))) best = f;
  }
  return best;
}

const char* factor_unit(double factor) {
  const double f = factor >= 1 ? factor : 1.0 / factor;
  for (const UnitsFactor& u : kUnitsFactors)
    if (std::abs(u.factor / f - 1.0) < 1e-9) return u.unit;
  return "";
}

// The usable parts' sizes in order, and what each part's neighbours are: the
// median of the others' sizes, their smallest and largest.
struct OtherSizes {
  std::vector<double> sorted;
  std::vector<size_t> rank;  ///< per part (usable ones), its index in `sorted`

  double at(size_t i, size_t skip) const { return sorted[i < skip ? i : i + 1]; }
  double median(size_t k) const {  // the middle one, or the geometric mean of the middle two
    const size_t m = sorted.size() - 1;
    if (m % 2) return at(m / 2, rank[k]);
    return std::sqrt(at(m / 2 - 1, rank[k]) * at(m / 2, rank[k]));
  }
  double smallest(size_t k) const { return at(0, rank[k]); }
  double largest(size_t k) const { return at(sorted.size() - 2, rank[k]); }
};

// Evidence from the place: `k` meets no other part's box, and scaled by
// 1/factor about the origin (a file in the assembly's coordinates, in another
// unit) its box meets one.
bool placed_like(const std::vector<UnitsLikePart>& parts, size_t k, double factor) {
  const Aabb& box = *parts[k].box;
  const Aabb scaled{box.lo / factor, box.hi / factor};
  bool meets_scaled = false;
  for (size_t j = 0; j < parts.size(); ++j) {
    if (j == k || !parts[j].box || !(size_of(*parts[j].box) > 0)) continue;
    if (box.overlaps(*parts[j].box)) return false;
    meets_scaled = meets_scaled || scaled.overlaps(*parts[j].box);
  }
  return meets_scaled;
}

}  // namespace

std::optional<std::string> setup_warning_kind(const std::string& warning) {
  for (const char* k : {kNonRigidPlacement, kUnitsLikeSize, kToleranceCoversPart,
                        kToleranceBelowResolution, kOpenMesh, kPlacedTwice}) {
    const std::string prefix = std::string(k) + ": ";
    if (warning.compare(0, prefix.size(), prefix) == 0) return std::string(k);
  }
  return std::nullopt;
}

std::string length_text(double value, const std::string& units) {
  return num(value) + " " + units;
}

std::optional<std::string> non_rigid_placement(const Mat4& transform) {
  const Eigen::Vector3d s =
      Eigen::JacobiSVD<Eigen::Matrix3d>(transform.topLeftCorner<3, 3>()).singularValues();
  if ((s.array() - 1.0).abs().maxCoeff() <= tol::kRigidPlacement) return std::nullopt;
  const bool uniform = s(0) - s(2) <= tol::kRigidPlacement * s(0);
  // CAD placements are rigid: a scale is almost always a units mistake.
  return std::string(kNonRigidPlacement) + ": the transform " +
         (uniform ? "scales by " + num(s(0))
                  : "stretches by (" + num(s(0)) + ", " + num(s(1)) + ", " + num(s(2)) +
                        ") along its principal axes (a non-uniform scale or a shear)") +
         "; CAD placements are rigid: is a unit conversion in the transform?";
}

double part_size(const Part& p) {
  return (p.box.hi - p.box.lo).maxCoeff();
}

std::vector<std::optional<UnitsLikeOutlier>> units_like_outliers(
    const std::vector<UnitsLikePart>& parts) {
  std::vector<std::optional<UnitsLikeOutlier>> out(parts.size());
  std::vector<size_t> usable;
  for (size_t k = 0; k < parts.size(); ++k)
    if (parts[k].box && size_of(*parts[k].box) > 0 && std::isfinite(size_of(*parts[k].box)))
      usable.push_back(k);
  if (usable.size() < 2) return out;
  OtherSizes others;
  others.rank.resize(parts.size());
  std::vector<size_t> order = usable;
  std::sort(order.begin(), order.end(), [&](size_t x, size_t y) {
    const double sx = size_of(*parts[x].box), sy = size_of(*parts[y].box);
    return sx < sy || (sx == sy && x < y);
  });
  for (size_t i = 0; i < order.size(); ++i) {
    others.sorted.push_back(size_of(*parts[order[i]].box));
    others.rank[order[i]] = i;
  }
  // Where two parts are off each other: the one whose format's unit says so
  // (2), else the one for which the factor leaves a unit (1).
  std::vector<int> likelier(parts.size(), 0);
  for (size_t k : usable) {
    if (parts[k].unit_from_file) continue;
    const double size = size_of(*parts[k].box), ref = others.median(k), ratio = size / ref;
    std::optional<double> factor;
    std::vector<std::string> why;
    // Its format's unit: a glTF part written in millimetres reads 1000 times too large.
    const UnitsLikePart& p = parts[k];
    if (p.format_unit && p.unit_mm > 1 && ratio >= tol::kUnitsLikeFormat) {
      factor = p.unit_mm;
      why.push_back("glTF declares metres, and many exporters write millimetres");
      likelier[k] = 2;
    }
    // Beyond every other part's size (the gap), and within a few per cent of a
    // factor of the others' median.
    const bool small = size * tol::kUnitsLikeGap <= others.smallest(k);
    const bool large = size >= others.largest(k) * tol::kUnitsLikeGap;
    if (!factor && usable.size() >= 3 && (small || large))
      for (int f = 0; f < kSizeFactors && !factor; ++f)
        for (const double want : {kUnitsFactors[f].factor, 1.0 / kUnitsFactors[f].factor})
          if (std::abs(ratio / want - 1.0) <= tol::kUnitsLikeFactor) {
            factor = want;
            why.push_back("within " + num(100 * tol::kUnitsLikeFactor) + " % of it");
          }
    // Its place: apart from every other part, where a factor puts it among
    // them in size and in place. Scaled up (a part read too small, which the
    // mistake moved towards the origin: scaled back it moves away, where only
    // its own place holds parts) from half the others' median; scaled down,
    // or by 10 (an exploded view's parts shrink into its middle), only from
    // beyond every other part's size.
    std::optional<double> placed;
    for (const UnitsFactor& u : kUnitsFactors)
      for (const double f : {u.factor, 1.0 / u.factor}) {
        const bool up = f < 1;
        const bool allowed =
            up ? small || (ratio * tol::kUnitsLikeRange <= 1 && u.factor != 10.0) : large;
        const double fixed = size / f;
        if (!allowed || fixed * tol::kUnitsLikeRange < others.smallest(k) ||
            fixed > others.largest(k) * tol::kUnitsLikeRange || !placed_like(parts, k, f))
          continue;
        if (!placed || std::abs(std::log(fixed / ref)) < std::abs(std::log(size / *placed / ref)))
          placed = f;
      }
    if (placed && (!factor || *factor == *placed)) {
      factor = placed;
      why.push_back("it meets no other part, and scaled by " +
                    (*placed < 1 ? num(1 / *placed) : "1/" + num(*placed)) +
                    " about the origin it meets one");
    }
    // So far off that no ordinary assembly has it.
    if (!factor && std::abs(std::log(ratio)) >= std::log(tol::kUnitsLikeFar)) {
      factor = nearest_factor(ratio, kSizeFactors);
      why.push_back("no ordinary assembly has a part " + num(tol::kUnitsLikeFar) +
                    " times larger or smaller than the others");
    }
    if (!factor) continue;
    if (!likelier[k] && unit_of(p.unit_mm / *factor)) likelier[k] = 1;
    UnitsLikeOutlier o;
    o.factor = *factor;
    o.size = size;
    o.reference = ref;
    for (size_t n = 0; n < why.size(); ++n) o.evidence += (n ? "; " : "") + why[n];
    out[k] = std::move(o);
  }
  // Two parts off each other (each the other's neighbour): the likelier one,
  // when one is.
  if (usable.size() == 2 && out[usable[0]] && out[usable[1]] &&
      likelier[usable[0]] != likelier[usable[1]])
    out[usable[likelier[usable[0]] > likelier[usable[1]] ? 1 : 0]].reset();
  return out;
}

std::string units_like_warning(const UnitsLikePart& part, const UnitsLikeOutlier& off,
                               const std::string& scene_units) {
  const bool big = off.factor > 1;
  const double f = big ? off.factor : 1.0 / off.factor;
  const double ratio = off.size / off.reference;
  char r[32];
  std::snprintf(r, sizeof r, "%.3g", ratio >= 1 ? ratio : 1 / ratio);
  std::string w = std::string(kUnitsLikeSize) + ": its size " + length_text(off.size, scene_units) +
                  " is " +
                  (ratio >= 1 ? std::string(r) + " times" : "1/" + std::string(r) + " of") +
                  " the median of the other parts' sizes, " +
                  length_text(off.reference, scene_units) + ": likely the " + factor_unit(f) +
                  "/mm factor " + (big ? num(f) : "1/" + num(f)) + " (" + off.evidence + ")";
  // The unit its file would be in: the one that makes it the factor smaller.
  if (const UnitsFactor* u = unit_of(part.unit_mm / off.factor))
    return w + ": if its file is in " + u->words + ", give the part \"units\": \"" + u->unit + "\"";
  return w + ": is its unit, or the other parts', right?";
}

std::string open_mesh_warning(long boundary_edges) {
  return std::string(kOpenMesh) + ": " + std::to_string(boundary_edges) +
         " boundary edges (edges of one triangle: a hole, a gap or a missing face in its "
         "surface), so it bounds no solid: a part inside it is found only through its hull, and "
         "a depth into it is its hull's or the deepest surface point's; is the export complete?";
}

std::optional<std::string> resolution_warning(double tolerance, double resolution,
                                              const std::string& units) {
  if (!(tolerance < resolution)) return std::nullopt;
  return std::string(kToleranceBelowResolution) + ": the tolerance " +
         length_text(tolerance, units) + " is below the part's coordinate resolution " +
         length_text(resolution, units) +
         " (the spacing of its stored coordinates at their magnitude): touching parts can show "
         "depths that large";
}

std::optional<std::string> tolerance_covers_part(double tolerance, const Part& a, const Part& b,
                                                 const std::string& units) {
  const Part& small = part_size(a) <= part_size(b) ? a : b;
  const double size = part_size(small);
  if (!(tolerance >= size)) return std::nullopt;
  return std::string(kToleranceCoversPart) + ": the tolerance " + length_text(tolerance, units) +
         " is at least the size of the smaller part (\"" + small.id + "\", " +
         length_text(size, units) + "): any overlap of this pair passes as a false positive";
}

}  // namespace pd
