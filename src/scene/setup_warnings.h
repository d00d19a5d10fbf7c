// Set-up smells that a run would otherwise absorb in silence (issue 25): a
// non-rigid placement, a part whose size is off its assembly's by a units
// factor, a tolerance that covers a whole part, a tolerance below a part's
// coordinate resolution. Each warning's text starts with its kind and ": ",
// so the CLI can say each kind once on stderr (setup_warning_kind).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/types.h"
#include "scene/parts.h"

namespace pd {

inline constexpr const char* kNonRigidPlacement = "placement not rigid";
inline constexpr const char* kUnitsLikeSize = "size off the assembly's by a units factor";
inline constexpr const char* kToleranceCoversPart = "tolerance covers a part";
inline constexpr const char* kToleranceBelowResolution = "tolerance below coordinate resolution";

/// The kind of a set-up warning (one of the constants above), or nullopt.
std::optional<std::string> setup_warning_kind(const std::string& warning);

/// A length with its unit, shortest exact-enough form ("0.0039 mm").
std::string length_text(double value, const std::string& units);

/// The warning for a part transform that is not rigid (its singular values
/// further than kRigidPlacement from 1), naming the factors; nullopt if rigid.
std::optional<std::string> non_rigid_placement(const Mat4& transform);

/// A part's size for the checks below: its box's largest extent (scene units).
double part_size(const Part& p);

struct UnitsLikeOutliers {
  double median = 0.0;                        ///< of the usable sizes (the lower one)
  std::vector<std::optional<double>> factor;  ///< per size; nullopt where none
};

/// Per entry of `sizes` (nullopt: an unusable part), the units-like factor
/// (25.4, 1000, 304.8 or 1/that, within kUnitsLikeFactor) by which it is off
/// the median of the usable sizes. Fewer than 3 usable sizes: no median worth
/// the name, nothing flagged.
UnitsLikeOutliers units_like_outliers(const std::vector<std::optional<double>>& sizes);

/// The warning for a part `units_like_outliers` flagged.
std::string units_like_warning(double size, double factor, double median, const std::string& units);

/// The warning for a tolerance below a part's coordinate resolution; nullopt
/// when it is not below.
std::optional<std::string> resolution_warning(double tolerance, double resolution,
                                              const std::string& units);

/// The warning for a false positive whose tolerance is at least the size of
/// the smaller part: any overlap of the pair would pass; nullopt otherwise.
std::optional<std::string> tolerance_covers_part(double tolerance, const Part& a, const Part& b,
                                                 const std::string& units);

}  // namespace pd
