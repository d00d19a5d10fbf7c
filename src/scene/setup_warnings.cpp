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

// The units factors against millimetres (in, m, ft) and what they suggest.
struct UnitsFactor {
  double factor;
  const char* name;
};
constexpr UnitsFactor kUnitsFactors[] = {{25.4, "inch/mm"}, {1000.0, "m/mm"}, {304.8, "ft/mm"}};

}  // namespace

std::optional<std::string> setup_warning_kind(const std::string& warning) {
  for (const char* k :
       {kNonRigidPlacement, kUnitsLikeSize, kToleranceCoversPart, kToleranceBelowResolution}) {
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

UnitsLikeOutliers units_like_outliers(const std::vector<std::optional<double>>& sizes) {
  std::vector<double> usable;
  for (const auto& s : sizes)
    if (s && *s > 0) usable.push_back(*s);
  UnitsLikeOutliers out;
  out.factor.resize(sizes.size());
  if (usable.size() < 3) return out;
  // The lower median: deterministic, and an actual part's size.
  auto mid = usable.begin() + (usable.size() - 1) / 2;
  std::nth_element(usable.begin(), mid, usable.end());
  const double median = out.median = *mid;
  for (size_t k = 0; k < sizes.size(); ++k) {
    if (!sizes[k] || !(*sizes[k] > 0)) continue;
    const double ratio = *sizes[k] / median;
    for (const UnitsFactor& f : kUnitsFactors)
      for (const double want : {f.factor, 1.0 / f.factor})
        if (std::abs(ratio / want - 1.0) <= tol::kUnitsLikeFactor) out.factor[k] = want;
  }
  return out;
}

std::string units_like_warning(double size, double factor, double median,
                               const std::string& units) {
  const bool big = factor > 1;
  const double f = big ? factor : 1.0 / factor;
  const char* name = "";
  for (const UnitsFactor& u : kUnitsFactors)
    if (std::abs(u.factor / f - 1.0) < 1e-9) name = u.name;
  return std::string(kUnitsLikeSize) + ": its size " + length_text(size, units) + " is " +
         (big ? num(f) + " times" : "1/" + num(f) + " of") + " the assembly's median part size " +
         length_text(median, units) + " (the " + name + " factor, within " +
         num(100 * tol::kUnitsLikeFactor) + " %): is its unit right?";
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
