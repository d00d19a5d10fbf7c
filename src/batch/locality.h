// Where each part sits, as one number: the refinement runs a part's pairs
// close together (batch/refine.cpp's order), so that its distances, built
// once, serve them all and go after the last.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/parts.h"

namespace pd {

/// A Morton code of each part's box centre over the box of every usable part
/// (0 for a part with an error): parts close in space get close codes. Only
/// orders work; no result depends on it.
std::vector<std::uint64_t> locality_codes(const std::vector<Part>& parts);

}  // namespace pd
