// What the report says of one part (docs/report-format.md, `parts`): made from
// the run by the report layer, read back by merge and --reuse. Its fields are
// described once, in results/part_fields.h, and serialised by the one codec
// (results/codec.h), as a pair result's are.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/types.h"

namespace pd {

/// Adding a field: declare it here and describe it once in for_each_field
/// (results/part_fields.h); the report and its readers follow
/// (tests/test_codec.cpp).
struct PartResult {
  std::string id;
  std::string source;  ///< the mesh path, or "inline"
  long vertices = 0;
  long hull_vertices = 0;
  long pieces = 0;  ///< convex pieces used: the decomposition's when one was made
  std::vector<std::string> warnings;
  std::optional<double> resolution;      ///< usable parts: the coordinates' spacing, scene units
  std::optional<Vec3> box_min, box_max;  ///< usable parts: the placed hull's box
  std::string content_hash;
  std::optional<bool> convex;
  /// tolerance auto: the worst measured chord sags, and a declared one.
  std::optional<double> sag_concave, sag_convex, sag_declared;
  /// B-rep parts: the deflection they were meshed at, the sag that mesh
  /// carries ("bound" or "estimate": tessellation_basis), scene units.
  std::optional<double> tessellation_deflection, tessellation_sag;
  std::string tessellation_basis;
  std::optional<double> decomposition_seconds;
  std::optional<bool> cached;      ///< the decomposition came from the cache
  std::string decomposition_note;  ///< the decomposition did not finish within its time box
  std::vector<std::string> tags;
  std::string group;                             ///< the part's product path
  std::optional<std::vector<std::string>> sets;  ///< with rules: the sets it is in
  std::optional<std::string> error;
};

}  // namespace pd
