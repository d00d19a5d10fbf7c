// A part's placement: its file's coordinates to scene units (the unit
// conversion, then the transform), and how much it stretches lengths.
#pragma once

#include "geometry/types.h"
#include "scene/scene.h"

namespace pd {

/// File coordinates to scene units: the unit conversion, then the transform.
Mat4 placement(const PartSpec& spec);

/// The placement's stretch factors, largest first.
Vec3 stretches(const Mat4& placement);

/// The largest factor by which the placement stretches a length.
double stretch(const Mat4& placement);

}  // namespace pd
