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
inline constexpr const char* kOpenMesh = "open mesh";
inline constexpr const char* kPlacedTwice = "part placed twice";

/// The kind of a set-up warning (one of the constants above), or nullopt.
std::optional<std::string> setup_warning_kind(const std::string& warning);

/// A length with its unit, shortest exact-enough form ("0.0039 mm").
std::string length_text(double value, const std::string& units);

/// The warning for a part transform that is not rigid (its singular values
/// further than kRigidPlacement from 1), naming the factors; nullopt if rigid.
std::optional<std::string> non_rigid_placement(const Mat4& transform);

/// A part's size for the checks below: its box's largest extent (scene units).
double part_size(const Part& p);

/// A part as the units check sees it.
struct UnitsLikePart {
  std::optional<Aabb> box;  ///< placed, scene units; nullopt: not usable
  double unit_mm = 1.0;     ///< millimetres per unit of its coordinates as read
  /// The unit its file format declares ("m": glTF), when it was read in it
  /// (no `units` of its own).
  std::optional<std::string> format_unit;
  /// Its file states its unit and the reader converts it (STEP): compared
  /// with, never flagged.
  bool unit_from_file = false;
};

/// Why a part's size looks like a units mistake.
struct UnitsLikeOutlier {
  double factor = 1.0;     ///< it reads this many times its likely size
  double size = 0.0;       ///< its size (scene units)
  double reference = 0.0;  ///< the median of the other usable parts' sizes
  std::string evidence;    ///< what makes the factor credible, in words
};

/// Per part, whether its size is off its neighbours' by a units factor
/// (tol::kUnitsLike*, docs/numerics.md "Units"): the factor and why. Each part
/// is compared with the median of the others' sizes, whatever their count (two
/// parts: each with the other). Where two parts flag each other, only the one
/// with evidence beyond the sizes (its format's unit, its place) is flagged
/// when one has it.
std::vector<std::optional<UnitsLikeOutlier>> units_like_outliers(
    const std::vector<UnitsLikePart>& parts);

/// The warning for a part `units_like_outliers` flagged: its size, the likely
/// factor, why, and the fix (the `units` to give it, `scene_units` the scene's).
std::string units_like_warning(const UnitsLikePart& part, const UnitsLikeOutlier& off,
                               const std::string& scene_units);

/// The warning for a part whose mesh has `boundary_edges` (> 0) edges of an
/// odd number of triangles (geometry/same_position.h): it bounds no solid.
std::string open_mesh_warning(long boundary_edges);

/// The warning for a tolerance below a part's coordinate resolution; nullopt
/// when it is not below.
std::optional<std::string> resolution_warning(double tolerance, double resolution,
                                              const std::string& units);

/// The warning for a false positive whose tolerance is at least the size of
/// the smaller part: any overlap of the pair would pass; nullopt otherwise.
std::optional<std::string> tolerance_covers_part(double tolerance, const Part& a, const Part& b,
                                                 const std::string& units);

}  // namespace pd
